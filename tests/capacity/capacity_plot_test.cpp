// The polar plot of `graspsim capacity --direction all`: drawn from the capacity.json that
// writeCapacityFiles writes (so the script and the file format are pinned to each other), and
// skipped with a reason, never thrown, when Python cannot draw it.

#include "graspsim/capacity/capacity_plot.h"

#include "graspsim/capacity/capacity_files.h"

#include "scratch_folder.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>


using namespace graspsim;
namespace fs = std::filesystem;

namespace {

capacity::GraspCapacity makeMeasurement(const std::string& name, const SimTK::Vec3& direction, bool torque, double onset) {
    capacity::GraspCapacity c;
    c.directionName = name;
    c.direction = SimTK::UnitVec3(direction);
    c.torque = torque;
    c.method = "ramp";
    c.rate = torque ? 0.1 : 2;
    c.trace.figures.slipped = true;
    c.trace.figures.slipOnsetLoad = onset;
    c.trace.figures.slipOnsetTime = onset / c.rate;
    return c;
}

std::vector<capacity::GraspCapacity> makeAllDirections() {
    std::vector<capacity::GraspCapacity> all;
    const char* names[] = {"x", "-x", "y", "-y", "z", "-z"};
    for (int k = 0; k < 6; ++k) {
        SimTK::Vec3 d(0);
        d[k / 2] = k % 2 ? -1 : 1;
        all.push_back(makeMeasurement(names[k], d, false, 5 + k));
    }
    for (int k = 0; k < 3; ++k) all.push_back(makeMeasurement(std::string(1, "xyz"[k]), SimTK::Vec3(k == 0, k == 1, k == 2), true, 0.1 * (k + 1)));
    return all;
}

class CapacityPlot : public graspsim::testing::ScratchFolder {
protected:
    void SetUp() override {
        ScratchFolder::SetUp();
        capacity::writeCapacityFiles(dir_.string(), "synthetic", makeAllDirections());
    }
    void TearDown() override {
        ScratchFolder::TearDown();
        ::unsetenv("GRASPSIM_PYTHON");
    }
};

}  // namespace

TEST_F(CapacityPlot, DrawsAPngFromTheWrittenCapacityJson) {
    const capacity::CapacityPlot plot = capacity::drawCapacityPlot(dir_.string());
    ASSERT_TRUE(plot.skipped.empty()) << plot.skipped;
    EXPECT_EQ(plot.file, (dir_ / "capacity.png").string());
    std::ifstream png(plot.file, std::ios::binary);
    std::string magic(8, '\0');
    png.read(magic.data(), 8);
    EXPECT_EQ(magic, std::string("\x89PNG\r\n\x1a\n", 8));
    EXPECT_TRUE(fs::exists(dir_ / "plot_capacity.py"));  // left to redraw or overlay runs
}

// A ramp that ends without slip has no onset; the plot draws it as a lower bound at the ramp's last
// load, from the keys it reads (analysis/plot_capacity.py's load: method, a null slip_onset_n,
// max_load_n; its drawing is checked by tests/analysis/plot_capacity_test.py). Oracle: the last
// sample's load, and the file as parsed JSON.
TEST_F(CapacityPlot, ARampWithoutSlipWritesTheLowerBoundThePlotDraws) {
    std::vector<capacity::GraspCapacity> all = makeAllDirections();
    capacity::GraspCapacity& held = all[3];  // -y
    held.trace.figures.slipped = false;
    held.trace.samples.resize(2);
    held.trace.samples[1].load = 2.0;
    capacity::writeCapacityFiles(dir_.string(), "synthetic", all);
    std::ifstream file(dir_ / "capacity.json");
    const nlohmann::json entry = nlohmann::json::parse(file)["measurements"][3];
    EXPECT_EQ(entry["direction"], "-y");
    EXPECT_EQ(entry["method"], "ramp");
    EXPECT_TRUE(entry["slip_onset_n"].is_null());
    EXPECT_EQ(entry["max_load_n"], 2.0);
    const capacity::CapacityPlot plot = capacity::drawCapacityPlot(dir_.string());
    EXPECT_TRUE(plot.skipped.empty()) << plot.skipped;
}

TEST_F(CapacityPlot, WithoutAnInterpreterItSaysWhyAndLeavesTheFiles) {
    ::setenv("GRASPSIM_PYTHON", "/nonexistent/python3", 1);
    const capacity::CapacityPlot plot = capacity::drawCapacityPlot(dir_.string());
    EXPECT_TRUE(plot.file.empty());
    EXPECT_NE(plot.skipped.find("/nonexistent/python3"), std::string::npos) << plot.skipped;
    EXPECT_FALSE(fs::exists(dir_ / "capacity.png"));
    EXPECT_TRUE(fs::exists(dir_ / "capacity.json"));
}

TEST_F(CapacityPlot, AFailingScriptIsSkippedWithItsLastLine) {
    std::ofstream(dir_ / "capacity.json") << "{ not json";
    const capacity::CapacityPlot plot = capacity::drawCapacityPlot(dir_.string());
    EXPECT_TRUE(plot.file.empty());
    EXPECT_NE(plot.skipped.find("plot_capacity.py failed"), std::string::npos) << plot.skipped;
}
