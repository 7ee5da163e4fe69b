// Runs `graspsim simulate`: bad input gets one line naming the field, exit code 2 and an empty
// output folder; a short run writes the three result files, identically when repeated.

#include "cli_process.h"

#include <gtest/gtest.h>

namespace fs = std::filesystem;
using graspsim::testing::RunResult;
using graspsim::testing::slurp;
using SimulateCommand = graspsim::testing::CliProcess;

namespace {

// A copy of the built-in ball scenario with one line replaced.
std::string ballScenarioWith(const std::string& from, const std::string& to) {
    std::string text = slurp(fs::path(GRASPSIM_SOURCE_DIR) / "models/scenarios/ball-clutch.yaml");
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

}  // namespace

TEST_F(SimulateCommand, ShortRunWritesTheResultFilesDeterministically) {
    const std::string out1 = (dir_ / "run1").string(), out2 = (dir_ / "run2").string();
    const RunResult a = run("simulate phone-pinch --duration 0.2 --out " + out1);
    ASSERT_EQ(a.exitCode, 0) << a.err;
    const RunResult b = run("simulate phone-pinch --duration 0.2 --out " + out2);
    ASSERT_EQ(b.exitCode, 0) << b.err;
    for (const char* file : {"trajectory.csv", "contacts.csv"}) {
        const std::string first = slurp(fs::path(out1) / file);
        EXPECT_GT(first.size(), 100u) << file;
        EXPECT_EQ(first, slurp(fs::path(out2) / file)) << file << " differs between two identical runs";
    }
    const std::string summary = slurp(fs::path(out1) / "summary.json");
    for (const char* key : {"\"scenario\"", "\"contact\"", "\"mode\"", "\"sim_time_s\"", "\"wall_time_s\"", "\"steps\"",
                            "\"mean_step_us\"", "\"ik_us_per_step\"", "\"dynamics_us_per_step\"",
                            "\"object_displacement_m\"", "\"max_penetration_m\"", "\"held\""}) {
        EXPECT_NE(summary.find(key), std::string::npos) << key;
    }
}

TEST_F(SimulateCommand, ApproxModeWritesTheSwitchEvents) {
    const std::string out = (dir_ / "approx").string();
    const RunResult r = run("simulate phone-pinch --mode approx --duration 1.1 --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::string events = slurp(fs::path(out) / "events.csv");
    EXPECT_EQ(events.rfind("time_s,event,grasp_quality_n,velocity_jump_m_s,reason\n", 0), 0u) << events;
    EXPECT_NE(events.find(",engage,"), std::string::npos) << events;
    const std::string summary = slurp(fs::path(out) / "summary.json");
    for (const char* key : {"\"engaged\": true", "\"engage_time_s\"", "\"release_time_s\": null", "\"q_at_engage_n\"",
                            "\"full_step_us\"", "\"approx_step_us\""}) {
        EXPECT_NE(summary.find(key), std::string::npos) << key << " in " << summary;
    }
}

TEST_F(SimulateCommand, RejectsBadOptionsWithoutTouchingTheOutputFolder) {
    const std::string out = " --out " + (dir_ / "out").string();
    expectBadInput("simulate juggling" + out, {"juggling", "ball-clutch"});
    expectBadInput("simulate ball-clutch --perturbation f7" + out, {"--perturbation", "f7"});
    expectBadInput("simulate ball-clutch --contact soft" + out, {"--contact", "soft", "compliant or rigid"});
    expectBadInput("simulate ball-clutch --integrator euler" + out, {"--integrator", "euler", "simbody or cvode"});
    expectBadInput("simulate ball-clutch --duration -1" + out, {"--duration", "-1"});
    expectBadInput("simulate ball-clutch --duration soon" + out, {"--duration", "soon"});
    expectBadInput("simulate ball-clutch --mode approx --q-threshold -1" + out, {"--q-threshold", "-1"});
    expectBadInput("simulate ball-clutch --mode approx --constraint hinge" + out, {"--constraint", "hinge", "weld"});
    expectBadInput("simulate ball-clutch --mode approx --q-threshold 1 --q-minimum 2" + out, {"--q-minimum", "2"});
    expectBadInput("simulate ball-clutch --mode approx --attach glued" + out, {"--attach", "glued", "merged or multi"});
    expectBadInput("simulate ball-clutch --mode approx --constraint weld --attach multi" + out, {"--attach", "multi", "weld"});
    EXPECT_FALSE(fs::exists(dir_ / "out"));
}

TEST_F(SimulateCommand, RejectsBadScenarioFilesNamingFileAndField) {
    extraFiles_ = 1;
    const std::string out = " --out " + (dir_ / "out").string();
    const auto check = [&](const std::string& from, const std::string& to, std::initializer_list<const char*> fragments) {
        const std::string file = write("bad.yaml", ballScenarioWith(from, to));
        std::vector<const char*> expected(fragments);
        expected.push_back("bad.yaml");
        const RunResult r = run("simulate " + file + out);
        EXPECT_EQ(r.exitCode, 2) << from << " -> " << to << "\n" << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        for (const char* f : expected) EXPECT_NE(r.err.find(f), std::string::npos) << "missing '" << f << "' in " << r.err;
        EXPECT_FALSE(fs::exists(dir_ / "out"));
    };
    check("static_friction: 0.9", "static_friction: -0.9", {"static_friction", "-0.9"});
    check("stiffness: 5.0e5", "stiffness: -5.0e5", {"stiffness"});
    check("mass: 0.200", "mas: 0.200", {"mas"});
    check("index_tip: [0.0199", "index_tip: [0.0599", {"goals.index_tip", "off"});
}
