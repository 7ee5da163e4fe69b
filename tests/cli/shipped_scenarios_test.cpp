// The planned scenarios shipped in models/scenarios (ball-tripod, can-power, key-lateral) are
// generated files: each is exactly what its `graspsim grasp plan` command (docs/planning.md)
// writes, so the copy is pinned to its source, the planner. Each runs by its built-in name,
// passes the set-up check at t = 0 and holds. Oracle for holding: the physical criterion of
// docs/planning.md, after settling (1 s) the object drifts < 5 mm in full compliant contact under
// gravity, here over 1 s (2 s simulated, to keep the suite short).

#include "cli_process.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <vector>

using graspsim::testing::RunResult;
using graspsim::testing::slurp;
using ShippedScenarios = graspsim::testing::CliProcess;
namespace fs = std::filesystem;

namespace {

struct Shipped {
    const char* name;
    const char* planArguments;  // as docs/planning.md gives them, without -o
};

const std::vector<Shipped> kShipped{
    {"ball-tripod", "grasp plan --type tripod --object sphere:radius=0.015,mass=0.03 --name ball-tripod"},
    {"can-power", "grasp plan --type power-cylinder --object cylinder:radius=0.035,length=0.12,mass=0.25 --name can-power"},
    {"key-lateral", "grasp plan --type lateral --object box:size=0.05x0.02x0.003,mass=0.02 --name key-lateral"},
};

}  // namespace

TEST_F(ShippedScenarios, EachIsWhatItsPlanCommandWrites) {
    for (const Shipped& s : kShipped) {
        const std::string written = (dir_ / (std::string(s.name) + ".yaml")).string();
        const RunResult r = run(std::string(s.planArguments) + " -o " + written);
        ASSERT_EQ(r.exitCode, 0) << s.name << ": " << r.err;
        const std::string shipped = slurp(fs::path(GRASPSIM_SOURCE_DIR) / "models/scenarios" / (std::string(s.name) + ".yaml"));
        EXPECT_FALSE(shipped.empty()) << s.name;
        EXPECT_EQ(slurp(written), shipped) << s.name << ": regenerate it with graspsim " << s.planArguments << " -o models/scenarios/"
                                           << s.name << ".yaml";
    }
}

TEST_F(ShippedScenarios, EachRunsByNameAndHoldsInFullContact) {
    for (const Shipped& s : kShipped) {
        const fs::path out = dir_ / s.name;
        const RunResult r = run(std::string("simulate ") + s.name + " --duration 2 -q --out " + out.string());
        ASSERT_EQ(r.exitCode, 0) << s.name << ": " << r.err;  // exit 2 if the set-up check refuses it
        const nlohmann::json summary = nlohmann::json::parse(slurp(out / "summary.json"));
        EXPECT_TRUE(summary["complete"].get<bool>()) << s.name;
        EXPECT_LE(summary["initial_penetration_m"].get<double>(), 0.001) << s.name;
        EXPECT_TRUE(summary["held"].get<bool>()) << s.name;
        EXPECT_LT(summary["object_displacement_m"].get<double>(), 0.005) << s.name;
    }
}
