// The grasp-types study (models/studies/grasp-types.yaml) in small: two subjects (the 50 kg,
// 1.52 m woman and the reference woman) x two grasp types (power-sphere, power-cylinder), each
// planned on load and simulated in full contact and with the approximation, through one
// `graspsim study run`. These are the cells that failed before the planner ran the set-up
// check's reach test itself (the reference woman's power sphere was refused, both women dropped
// the cylinder). Oracle: the hold criterion of docs/planning.md, in every full-contact case the
// object drifts < 5 mm over the 2 s after settling and no segment is > 1 mm inside it at t = 0;
// in every approx case the approximation engages; and results.md says so in each cell.

#include "cli_process.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

namespace fs = std::filesystem;
using graspsim::testing::RunResult;
using graspsim::testing::slurp;
using GraspTypesStudy = graspsim::testing::CliProcess;

TEST_F(GraspTypesStudy, BothWomenHoldThePlannedPowerSphereAndCylinderAndTheApproximationEngages) {
    const std::string bases = std::string(GRASPSIM_SOURCE_DIR) + "/models/studies/grasp-types/";
    const std::string study = write("small.yaml", "name: grasp-types-small\n"
                                                  "base: [" + bases + "power-sphere.yaml, " + bases + "power-cylinder.yaml]\n"
                                                  "axes:\n"
                                                  "  subject:\n"
                                                  "    - {sex: female, mass: 50, stature: 1.52}\n"
                                                  "    - {sex: female}\n"
                                                  "  mode: [full, approx]\n"
                                                  "measures: [held, engaged, object_displacement_m, initial_penetration_m, plan_time_s]\n");
    extraFiles_ = 1;
    const fs::path out = dir_ / "out";
    const RunResult r = run("study run " + study + " --out " + out.string() + " --jobs 2");
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
    int full = 0, approx = 0;
    for (const auto& entry : fs::directory_iterator(out / "cases")) {
        const nlohmann::json s = nlohmann::json::parse(slurp(entry.path() / "summary.json"));
        const std::string where = entry.path().string();
        EXPECT_GT(s["plan_time_s"].get<double>(), 0) << where;  // planned on load
        EXPECT_LE(s["initial_penetration_m"].get<double>(), 0.001) << where;
        if (s["mode"] == "full") {
            ++full;
            EXPECT_TRUE(s["held"].get<bool>()) << where;
            EXPECT_LT(s["object_displacement_m"].get<double>(), 0.005) << where;
        } else {
            ++approx;
            EXPECT_TRUE(s["engaged"].get<bool>()) << where;
        }
    }
    EXPECT_EQ(full, 4);
    EXPECT_EQ(approx, 4);
    const std::string table = slurp(out / "results.md");
    std::size_t cells = 0;
    for (std::size_t at = 0; (at = table.find("held, drift", at)) != std::string::npos; ++at) ++cells;
    EXPECT_EQ(cells, 4u) << table;
    EXPECT_EQ(table.find("DROPPED"), std::string::npos) << table;
    EXPECT_EQ(table.find("NOT engaged"), std::string::npos) << table;
}
