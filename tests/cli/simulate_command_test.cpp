// Runs `graspsim simulate`: bad input gets one line naming the field, exit code 2 and an empty
// output folder; a short run writes the result files, byte-identically when repeated; a run that
// diverges exits with 3 and an incomplete summary.

#include "cli_process.h"

#include <fstream>

#include <gtest/gtest.h>

#include <sstream>
#include <tuple>
#include <utility>
#include <vector>

namespace fs = std::filesystem;
using graspsim::testing::RunResult;
using graspsim::testing::slurp;
using SimulateCommand = graspsim::testing::CliProcess;

namespace {

// A copy of a shipped scenario with one line replaced.
std::string shippedScenarioWith(const std::string& name, const std::string& from, const std::string& to) {
    std::string text = slurp(fs::path(GRASPSIM_SOURCE_DIR) / "models/scenarios" / (name + ".yaml"));
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

std::string ballScenarioWith(const std::string& from, const std::string& to) {
    return shippedScenarioWith("ball-clutch", from, to);
}

}  // namespace

// The same command twice gives byte-identical trajectory.csv and contacts.csv, for every contact
// model and mode. The run covers the release, free contact, the grasp switch's engagement (approx)
// and a perturbation: the approach and settling are shortened in a copy of the phone scenario
// (the held weight is inside the grasp's limits, so the switch engages, at 0.31 s; the pull starts
// at 0.35 s and releases it).
// Rigid contact runs full contact only (the approximation runs on compliant contact).
class SimulateTwice : public graspsim::testing::CliProcess,
                      public ::testing::WithParamInterface<std::tuple<const char*, const char*>> {};

TEST_P(SimulateTwice, GivesByteIdenticalTrajectoryAndContacts) {
    extraFiles_ = 1;
    std::string text = slurp(fs::path(GRASPSIM_SOURCE_DIR) / "models/scenarios/phone-pinch.yaml");
    for (const auto& [from, to] : {std::pair<std::string, std::string>{"approach_time: 0.5 ", "approach_time: 0.05"},
                                   {"settle_time: 1.0 ", "settle_time: 0.15"},
                                   {"start: 1.5, duration: 1.0}   # pulls", "start: 0.35, duration: 0.1}   # pulls"}}) {
        const std::size_t at = text.find(from);
        ASSERT_NE(at, std::string::npos) << from;
        text.replace(at, from.size(), to);
    }
    const std::string scenario = write("short.yaml", text);
    const auto [contact, mode] = GetParam();
    const std::string args = "simulate " + scenario + " --contact " + contact + " --mode " + mode +
                             " --perturbation f1 --duration 0.5 --out ";
    const std::string out1 = (dir_ / "run1").string(), out2 = (dir_ / "run2").string();
    const RunResult a = run(args + out1);
    ASSERT_EQ(a.exitCode, 0) << a.err;
    const RunResult b = run(args + out2);
    ASSERT_EQ(b.exitCode, 0) << b.err;
    for (const char* file : {"trajectory.csv", "contacts.csv"}) {
        const std::string first = slurp(fs::path(out1) / file);
        EXPECT_GT(first.size(), 100u) << file;
        EXPECT_EQ(first, slurp(fs::path(out2) / file)) << file << " differs between two identical runs";
    }
    // The runs did reach the phases they are meant to cover.
    EXPECT_NE(slurp(fs::path(out1) / "contacts.csv").find("index"), std::string::npos);
    if (std::string(mode) == "approx") EXPECT_NE(a.out.find("engaged at"), std::string::npos) << a.out;
}

INSTANTIATE_TEST_SUITE_P(ContactAndMode, SimulateTwice,
                         ::testing::Combine(::testing::Values("compliant"), ::testing::Values("full", "approx")),
                         [](const auto& info) {
                             return std::string(std::get<0>(info.param)) + "_" + std::get<1>(info.param);
                         });
INSTANTIATE_TEST_SUITE_P(RigidContact, SimulateTwice, ::testing::Combine(::testing::Values("rigid"), ::testing::Values("full")),
                         [](const auto& info) {
                             return std::string(std::get<0>(info.param)) + "_" + std::get<1>(info.param);
                         });

TEST_F(SimulateCommand, ShortRunWritesTheSummary) {
    const std::string out = (dir_ / "run").string();
    // A folder reused from an approx run with --view: its switch events and replay are not this run's.
    fs::create_directories(out);
    for (const char* name : {"events.csv", "constraint.csv", "replay.html", "replay.png"}) std::ofstream(fs::path(out) / name) << "an earlier run's";
    const RunResult a = run("simulate phone-pinch --duration 0.2 --out " + out);
    ASSERT_EQ(a.exitCode, 0) << a.err;
    const std::string summary = slurp(fs::path(out) / "summary.json");
    for (const char* key : {"\"scenario\"", "\"contact\"", "\"mode\"", "\"sim_time_s\"", "\"wall_time_s\"", "\"steps\"",
                            "\"mean_step_us\"", "\"ik_us_per_step\"", "\"dynamics_us_per_step\"",
                            "\"object_displacement_m\"", "\"max_penetration_m\"", "\"initial_penetration_m\"", "\"held\"", "\"complete\": true"}) {
        EXPECT_NE(summary.find(key), std::string::npos) << key;
    }
    // 0.2 s ends inside the 0.5 s approach, when the phone is still fixed: no hold to report.
    EXPECT_NE(a.out.find("hold not tested (the object is fixed for the approach until 0.5 s)"), std::string::npos) << a.out;
    EXPECT_EQ(a.out.find("held yes"), std::string::npos) << a.out;
    for (const char* name : {"events.csv", "constraint.csv", "replay.html", "replay.png"}) EXPECT_FALSE(fs::exists(fs::path(out) / name)) << name;
    // 0.7 s ends after the release but before the 1 s settle time: held, with no drift to report.
    const RunResult b = run("simulate ball-clutch --duration 0.7 -q --out " + (dir_ / "unsettled").string());
    ASSERT_EQ(b.exitCode, 0) << b.err;
    EXPECT_NE(b.out.find("(the run ended before the settle time, 1 s: no drift after settling measured)"), std::string::npos) << b.out;
    EXPECT_EQ(b.out.find("mm after settling"), std::string::npos) << b.out;
}

// contacts.csv names the object as the scenario does, whatever its shape: body_b is "object" and
// shape_b the scenario's shape. The same phone given as a box and as a mesh (box.stl scaled to the
// phone's size), and the ball: before, "phone,phone_box" (any box, a key as well), "mesh,mesh_shape"
// and "ball,ball_sphere".
TEST_F(SimulateCommand, ContactsNameTheObjectAsTheScenarioDoesWhateverItsShape) {
    std::string phoneMesh = slurp(fs::path(GRASPSIM_SOURCE_DIR) / "models/scenarios/phone-pinch.yaml");
    for (const auto& [from, to] : {std::pair<std::string, std::string>{"shape: box", "shape: mesh"},
                                   {"size: [0.070, 0.140, 0.008]", "mesh: " GRASPSIM_TEST_DATA_DIR "/meshes/box.stl\n"
                                                                   "  scale: [1.75, 2.3333333333333335, 0.4]"}}) {
        const std::size_t at = phoneMesh.find(from);
        ASSERT_NE(at, std::string::npos) << from;
        phoneMesh.replace(at, from.size(), to);
    }
    const std::string meshScenario = write("phone_mesh.yaml", phoneMesh);
    for (const auto& [scenario, shape] : {std::pair<std::string, std::string>{"phone-pinch", "box"},
                                          {meshScenario, "mesh"},
                                          {"ball-clutch", "sphere"}}) {
        const std::string out = (dir_ / shape).string();
        const RunResult r = run("simulate " + scenario + " --duration 0.1 -q --out " + out);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        std::istringstream contacts(slurp(fs::path(out) / "contacts.csv"));
        std::string line;
        std::getline(contacts, line);
        ASSERT_EQ(line.rfind("time_s,body_a,shape_a,body_b,shape_b,", 0), 0u) << line;
        int rows = 0;
        for (; std::getline(contacts, line); ++rows) {
            std::vector<std::string> fields;
            std::istringstream row(line);
            for (std::string field; fields.size() < 5 && std::getline(row, field, ',');) fields.push_back(field);
            ASSERT_EQ(fields.size(), 5u) << line;
            EXPECT_EQ(fields[3], "object") << scenario << ": " << line;
            EXPECT_EQ(fields[4], shape) << scenario << ": " << line;
        }
        EXPECT_GT(rows, 0) << scenario << ": the fingers reach the object within 0.1 s";
    }
}

// With --view the run's result comes first, where a reader looks (and the approximation's line
// after it in approx mode); the last line points at the replay the run wrote.
TEST_F(SimulateCommand, WithViewTheResultComesFirstAndTheReplayLineLast) {
    for (const std::string mode : {"full", "approx"}) {
        const std::string out = (dir_ / mode).string();
        const RunResult r = run("simulate ball-clutch --mode " + mode + " --duration 0.05 -q --view --out " + out);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        std::vector<std::string> lines;
        std::istringstream text(r.out);
        for (std::string line; std::getline(text, line);) lines.push_back(line);
        ASSERT_EQ(lines.size(), mode == "full" ? 2u : 3u) << r.out;
        const std::string result = "ball-clutch (compliant, " + mode + ", perturbation none): 0.05 s simulated in ";
        EXPECT_EQ(lines.front().substr(0, result.size()), result) << r.out;
        if (mode == "approx") EXPECT_EQ(lines[1].rfind("approximation (", 0), 0u) << r.out;
        EXPECT_EQ(lines.back(), "replay written to " + out + "/replay.html: open it in a web browser") << r.out;
        EXPECT_TRUE(fs::is_regular_file(fs::path(out) / "replay.html"));
    }
}

// --capsule-contact ends reaches the run's scenario, which scenario.yaml records; the default
// writes nothing new.
TEST_F(SimulateCommand, TheCapsuleRuleGivenIsRecordedInScenarioYaml) {
    for (const bool ends : {false, true}) {
        const std::string out = (dir_ / (ends ? "ends" : "deepest")).string();
        const RunResult r =
            run(std::string("simulate phone-pinch --duration 0.1 -q") + (ends ? " --capsule-contact ends" : "") + " --out " + out);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(slurp(fs::path(out) / "scenario.yaml").find("capsule_contact: ends") != std::string::npos, ends);
    }
}

// The OpenSim files beside the CSVs: motion.mot has a row per trajectory.csv row and a column per
// joint, labelled as trajectory.csv's joint columns; external_loads.xml names object_forces.sto.
TEST_F(SimulateCommand, ShortRunWritesTheOpenSimFiles) {
    const std::string out = (dir_ / "run").string();
    const RunResult a = run("simulate phone-pinch --duration 0.1 --out " + out);
    ASSERT_EQ(a.exitCode, 0) << a.err;
    std::istringstream trajectory(slurp(fs::path(out) / "trajectory.csv")), motion(slurp(fs::path(out) / "motion.mot"));
    std::string header, line;
    std::getline(trajectory, header);
    int rows = 0;
    while (std::getline(trajectory, line)) ++rows;
    std::vector<std::string> motionLines;
    while (std::getline(motion, line)) motionLines.push_back(line);
    ASSERT_GT(motionLines.size(), 7u);
    EXPECT_EQ(motionLines[2], "nRows=" + std::to_string(rows));
    EXPECT_EQ(motionLines[4], "inDegrees=yes");
    EXPECT_EQ(motionLines.size(), 7u + rows);
    // trajectory.csv: time, 3 position, 4 quaternion, quality, then <joint>_rad; motion.mot: time, <joint>.
    std::string expected = "time", field;
    std::istringstream columns(header);
    for (int k = 0; std::getline(columns, field, ','); ++k) {
        if (k >= 9) expected += "\t" + field.substr(0, field.size() - 4);
    }
    EXPECT_EQ(motionLines[6], expected);
    EXPECT_NE(slurp(fs::path(out) / "external_loads.xml").find("<datafile>object_forces.sto</datafile>"), std::string::npos);
    EXPECT_EQ(slurp(fs::path(out) / "object_forces.sto").rfind("object_forces\nversion=1\n", 0), 0u);
}

// A scenario that passes every check but cannot be integrated: a perturbation of 1e300 N (any
// finite force is accepted) throws the released phone out of double range. The run stops early
// with exit code 3, a message naming the failure, and complete result files up to it, marked
// incomplete in summary.json.
TEST_F(SimulateCommand, NumericalFailureExitsWithThreeAndMarksTheSummaryIncomplete) {
    extraFiles_ = 1;
    std::string text = slurp(fs::path(GRASPSIM_SOURCE_DIR) / "models/scenarios/phone-pinch.yaml");
    const std::string from = "f1: {force: [-2.0, 0, 0], start: 1.5, duration: 1.0}";
    const std::size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos);
    text.replace(at, from.size(), "f1: {force: [-1.0e300, 0, 0], start: 0.55, duration: 0.1}");
    const std::string out = (dir_ / "out").string();
    const RunResult r = run("simulate " + write("diverges.yaml", text) + " --perturbation f1 --duration 0.7 --out " + out);
    EXPECT_EQ(r.exitCode, 3) << r.out << r.err;
    EXPECT_NE(r.err.find("graspsim: simulation stopped early"), std::string::npos) << r.err;
#ifndef GRASPSIM_SANITIZED  // there CPodes' own error block reaches stderr too (io/filtered_stderr.h)
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
    EXPECT_EQ(r.err.find("SimTK Exception thrown at"), std::string::npos) << r.err;
#endif
    const std::string summary = slurp(fs::path(out) / "summary.json");
    EXPECT_NE(summary.find("\"complete\": false"), std::string::npos) << summary;
    EXPECT_NE(summary.find("\"failure\""), std::string::npos) << summary;
    // Samples up to the failure are kept: the header plus the samples before 0.55 s.
    const std::string trajectory = slurp(fs::path(out) / "trajectory.csv");
    EXPECT_GE(std::count(trajectory.begin(), trajectory.end(), '\n'), 1 + 55) << trajectory.substr(0, 200);
}

// Fixed steps of 5 ms blow the ball tripod up as its fingers close, where the error-controlled run
// and fixed 1 ms steps hold it (docs/performance.md). The stepper stops at the step whose error
// estimate exceeds the state's own scale (from 0.5 s): one line naming where the step came from
// (the scenario's simulation.step_size, or --step-size), its value and what to use, exit 2, no
// folder. At the 1 ms it suggests, the ball clutch runs and writes its results.
TEST_F(SimulateCommand, AFixedStepTheStepperCannotTrustIsRefusedWithoutOutput) {
    const std::string out = " --out " + (dir_ / "out").string();
    const std::string file =
        write("tripod-5ms.yaml", shippedScenarioWith("ball-tripod", "  settle_time:", "  step_size: 0.005\n  settle_time:"));
    extraFiles_ = 1;
    // 664 times the scale: far from the threshold, where the ball clutch's 1.02 is refused by a hair.
    expectBadInput("simulate " + file + " --integrator implicit-fixed --duration 1" + out,
                   {"simulation.step_size: 0.005 s", "implicit-fixed", "t = 0.5000 s", "--step-size", "--integrator implicit"});
    expectBadInput("simulate ball-tripod --mode approx --integrator implicit-fixed --step-size 0.005 --duration 1" + out,
                   {"--step-size: 0.005 s", "t = 0.5000 s"});
    const RunResult r = run("simulate ball-clutch --integrator implicit-fixed --step-size 0.001 --duration 1" + out);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir_ / "out" / "summary.json"));
}

// Where neither the run nor the scenario gives a step, implicit-fixed takes 1 ms
// (simulation::kDefaultFixedStepSize), at which the tripod that 5 ms throws holds: 1.2 s in
// exactly 1200 steps (the fixed step's count), held after settling (its goals within the held
// tolerance, the run's own check).
TEST_F(SimulateCommand, ImplicitFixedWithoutAStepTakesTheDefaultMillisecondAndHoldsTheTripod) {
    const std::string out = (dir_ / "fixed").string();
    const RunResult r = run("simulate ball-tripod --integrator implicit-fixed --duration 1.2 --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("1200 steps, held yes"), std::string::npos) << r.out;
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
                            "\"engage_obstacle_at_end\": null", "\"full_step_us\"", "\"approx_step_us\""}) {
        EXPECT_NE(summary.find(key), std::string::npos) << key << " in " << summary;
    }
}

TEST_F(SimulateCommand, RejectsBadOptionsWithoutTouchingTheOutputFolder) {
    const std::string out = " --out " + (dir_ / "out").string();
    expectBadInput("simulate juggling" + out, {"juggling", "ball-clutch"});
    expectBadInput("simulate ball-clutch --perturbation f7" + out, {"--perturbation", "f7"});
    expectBadInput("simulate ball-clutch --contact soft" + out, {"--contact", "soft", "compliant or rigid"});
    expectBadInput("simulate ball-clutch --integrator euler" + out, {"--integrator", "euler", "implicit or implicit-fixed"});
    expectBadInput("simulate ball-clutch --integrator implicit --step-size 0" + out, {"--step-size", "0", "> 0"});
    expectBadInput("simulate ball-clutch --integrator implicit --step-size nan" + out, {"--step-size", "nan"});
    expectBadInput("simulate ball-clutch --integrator implicit --step-size -1e-3" + out, {"--step-size", "-1e-3"});
    // The anchors' explicit relaxation: stable up to 2 x anchor_relaxation_time (1 ms by default);
    // on the ball clutch 2 ms runs and 2.5 ms ended in a raw Simbody NaN trace at 0.08 s.
    expectBadInput("simulate ball-clutch --friction anchor --integrator implicit-fixed --step-size 0.0025" + out,
                   {"--step-size", "0.0025", "anchor_relaxation_time", "0.002 s", "--integrator implicit"});
    expectBadInput("simulate ball-clutch --friction lugre" + out, {"--friction", "lugre", "regularized or anchor"});
    expectBadInput("simulate ball-clutch --contact rigid --friction anchor" + out, {"--friction", "anchor", "rigid"});
    expectBadInput("simulate ball-clutch --capsule-contact both" + out, {"--capsule-contact", "both", "deepest or ends"});
    expectBadInput("simulate ball-clutch --contact rigid --capsule-contact ends" + out, {"--capsule-contact", "ends", "rigid"});
    expectBadInput("simulate ball-clutch --duration -1" + out, {"--duration", "-1"});
    expectBadInput("simulate ball-clutch --duration soon" + out, {"--duration", "soon"});
    expectBadInput("simulate ball-clutch --mode approx --q-threshold -1" + out, {"--q-threshold", "-1"});
    expectBadInput("simulate ball-clutch --mode approx --constraint hinge" + out, {"--constraint", "hinge", "weld"});
    expectBadInput("simulate ball-clutch --mode approx --q-threshold 1 --q-minimum 2" + out, {"--q-minimum", "2"});
    expectBadInput("simulate ball-clutch --mode approx --attach glued" + out, {"--attach", "glued", "merged or multi"});
    expectBadInput("simulate ball-clutch --mode approx --limits box" + out, {"--limits", "box", "thesis", "contact", "compliance"});
    expectBadInput("simulate ball-clutch --mode approx --constraint weld --limits compliance" + out,
                   {"--limits", "compliance", "weld", "two-sided", "--constraint bushing"});
    expectBadInput("simulate ball-clutch --mode approx --attach multi --limits compliance" + out, {"--limits", "compliance", "multi"});
    expectBadInput("simulate ball-clutch --mode approx --constraint weld --attach multi" + out, {"--attach", "multi", "weld"});
    expectBadInput("simulate ball-clutch --mode approx --release-at slip" + out, {"--release-at", "slip", "none or compliance"});
    expectBadInput("simulate ball-clutch --mode approx --constraint weld --release-at compliance" + out,
                   {"--release-at", "compliance", "weld", "--constraint bushing"});
    expectBadInput("simulate ball-clutch --mode approx --attach multi --release-at compliance" + out, {"--release-at", "multi"});
    expectBadInput("simulate ball-clutch --mode approx --release-give=-1" + out, {"--release-give", "-1", "> 0 (m)"});
    expectBadInput("simulate ball-clutch --mode approx --release-at none --release-give 0.002" + out,
                   {"--release-give", "compliance release trigger", "none"});
    // The approximation's options without --mode approx would be silently unused.
    expectBadInput("simulate ball-clutch --constraint weld" + out,
                   {"--constraint: value 'weld' is not accepted with --mode full", "add --mode approx or leave --constraint out"});
    expectBadInput("simulate ball-clutch --mode full --q-minimum 0.1" + out, {"--q-minimum: value '0.1'", "--mode full"});
    expectBadInput("simulate ball-clutch --limits contact" + out, {"--limits: value 'contact'", "--mode full"});
    expectBadInput("simulate ball-clutch --release-give 0.001" + out, {"--release-give: value '0.001'", "--mode full"});
    expectBadInput("simulate ball-clutch --mode approx --release-creep 1" + out, {"--release-creep", "'1'", "on or off"});
    expectBadInput("simulate ball-clutch --mode approx --constraint weld --release-creep on" + out,
                   {"--release-creep", "compliance release trigger", "none"});
    expectBadInput("simulate ball-clutch --mode approx --bushing-give soft" + out, {"--bushing-give", "soft", "auto, stiff, model or coupled"});
    expectBadInput("simulate ball-clutch --mode approx --constraint weld --bushing-give model" + out,
                   {"--bushing-give", "model", "merged bushing", "weld merged"});
    expectBadInput("simulate ball-clutch --bushing-give model" + out, {"--bushing-give: value 'model'", "--mode full"});
    expectBadInput("simulate phone-pinch --ramp up" + out, {"--ramp", "'up'", "x, y, z, -x, -y, -z or three numbers"});
    expectBadInput("simulate phone-pinch --ramp 0,0,0" + out, {"--ramp", "'0,0,0'"});
    expectBadInput("simulate phone-pinch --ramp all" + out, {"--ramp", "'all'", "one direction"});
    expectBadInput("simulate phone-pinch --ramp -y --ramp-rate 0" + out, {"--ramp-rate", "0", "> 0 (N/s)"});
    expectBadInput("simulate phone-pinch --ramp-rate 2" + out, {"--ramp-rate", "without --ramp"});
    expectBadInput("simulate phone-pinch --ramp-torque" + out, {"--ramp-torque", "without --ramp"});
    // The phone settles to 1 s: a run that ends before its load starts at 1.1 s has no ramp to show.
    expectBadInput("simulate phone-pinch --ramp -y --duration 0.5" + out, {"--ramp", "starts at 1.1 s", "end at 0.5 s", "--duration"});
    // About the line through the phone's two goals nothing resists (capacity refuses it too).
    expectBadInput("simulate phone-pinch --ramp 0.8866,-0.4599,-0.0500 --ramp-torque" + out,
                   {"--ramp 0.8866,-0.4599,-0.0500 --ramp-torque", "index_tip and thumb_tip"});
    EXPECT_FALSE(fs::exists(dir_ / "out"));
}

// --ramp puts capacity's load into a simulation (to replay it with --view). The oracle is
// `graspsim capacity` with the same load (the second method): the phone is still held shortly
// before the slip onset the capacity run found, and no longer held shortly after its drop.
TEST_F(SimulateCommand, ARampSlipsAndDropsTheObjectWhenCapacitySaysItDoes) {
    const std::string cap = (dir_ / "cap").string();
    ASSERT_EQ(run("capacity phone-pinch --rate 8 --max-duration 0.6 --out " + cap).exitCode, 0);
    const std::string json = slurp(fs::path(cap) / "capacity.json");
    const auto number = [&](const std::string& key) {
        const std::size_t at = json.find("\"" + key + "\": ");
        return at == std::string::npos ? -1.0 : std::stod(json.substr(at + key.size() + 4));
    };
    const double onset = number("slip_onset_time_s"), drop = number("drop_time_s");
    ASSERT_GT(onset, 1.1) << json;
    ASSERT_GT(drop, onset) << json;
    const auto simulateUntil = [&](double duration) {
        const std::string out = (dir_ / ("sim" + std::to_string(duration))).string();
        const RunResult r = run("simulate phone-pinch --ramp -y --ramp-rate 8 -q --duration " + std::to_string(duration) + " --out " + out);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        EXPECT_NE(r.out.find("ramp -y force 8 N/s from 1.1 s"), std::string::npos) << r.out;
        EXPECT_NE(slurp(fs::path(out) / "provenance.json").find("\"ramp\": \"-y force 8 N/s from 1.1 s\""), std::string::npos);
        return r.out;
    };
    EXPECT_NE(simulateUntil(onset - 0.05).find("held yes"), std::string::npos);
    EXPECT_NE(simulateUntil(drop + 0.05).find("held no"), std::string::npos);
}

// A Q_M at or above the automatic Q_Th (known only once the grasp has settled, 0.203 N on the ball
// clutch) would release every engagement at once: the run chattered through 60 engage/release
// events in 0.6 s and exited 0. Now it is bad input, found at the settled check: one line naming
// Q_M, its value and the threshold, exit 2, no folder. Q_M just below passes the same check.
TEST_F(SimulateCommand, AQMinimumNotBelowTheAutomaticThresholdIsBadInput) {
    const std::string out = " --out " + (dir_ / "out").string();
    expectBadInput("simulate ball-clutch --mode approx --duration 1.1 --q-minimum 1000" + out,
                   {"--q-minimum", "1000 N", "must be below Q_Th", "0.203"});
    const RunResult ok = run("simulate ball-clutch --mode approx --duration 1.1 -q --q-minimum 0.2" + out);
    EXPECT_EQ(ok.exitCode, 0) << ok.err;
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
    check("stiffness: 5.0e5", "stiffness: 5.0e5\n  anchor_damping_mass: -0.02", {"contact.anchor_damping_mass", "-0.02"});
    check("mass: 0.200", "mas: 0.200", {"mas"});
    check("index_tip: [0.0199", "index_tip: [0.0599", {"goals.index_tip", "off"});
}

// Object shapes: an unknown shape, a non-positive size or mass, a missing size field, and each
// kind of unusable mesh file are one line naming the scenario file and field, exit 2, no output.
TEST_F(SimulateCommand, RejectsBadObjectShapesAndMeshes) {
    extraFiles_ = 1;
    const std::string out = " --out " + (dir_ / "out").string();
    const auto check = [&](const std::string& text, std::initializer_list<const char*> fragments) {
        const std::string file = write("bad.yaml", text);
        const RunResult r = run("simulate " + file + out);
        EXPECT_EQ(r.exitCode, 2) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_NE(r.err.find("bad.yaml:"), std::string::npos) << r.err;
        for (const char* f : fragments) EXPECT_NE(r.err.find(f), std::string::npos) << "missing '" << f << "' in " << r.err;
        EXPECT_FALSE(fs::exists(dir_ / "out"));
    };
    check(ballScenarioWith("shape: sphere", "shape: cone"), {"object.shape", "cone", "cylinder, capsule, ellipsoid or mesh"});
    check(ballScenarioWith("radius: 0.045", "radius: 0"), {"object.radius", "'0'", "> 0"});
    check(ballScenarioWith("mass: 0.200", "mass: -0.2"), {"object.mass", "-0.2", "> 0"});
    check(ballScenarioWith("shape: sphere", "shape: cylinder"), {"object.length", "is missing"});
    check(ballScenarioWith("shape: sphere", "shape: ellipsoid"), {"object.radius", "semi_axes"});
    const std::string meshes = GRASPSIM_TEST_DATA_DIR "/meshes/";
    const auto meshScenario = [&](const std::string& file) {
        std::string text = ballScenarioWith("shape: sphere", "shape: mesh");
        text.replace(text.find("radius: 0.045"), 13, "mesh: " + meshes + file);
        return text;
    };
    check(meshScenario("no_such_mesh.stl"), {"object.mesh", "no_such_mesh.stl", "not a readable file"});
    check(meshScenario("empty.stl"), {"object.mesh", "empty.stl", "is empty"});
    check(meshScenario("open_box.stl"), {"object.mesh", "open_box.stl", "not closed"});
    check(meshScenario("l_shape.obj"), {"object.mesh", "l_shape.obj", "not convex", "convex hull has volume"});
    check(meshScenario("inverted_box.stl"), {"object.mesh", "inverted_box.stl", "inverted normals"});
}

// The set-up check (setup_check.h): the reference scenario on a 50 kg, 1.52 m woman with its
// hand-found pose starts with a finger inside the ball. One line naming the file, the segment and
// the depth (the depth itself is checked against a closed form in setup_check_test), exit 2, and
// no output folder.
TEST_F(SimulateCommand, GraspThatStartsInsideTheObjectIsRefused) {
    extraFiles_ = 1;
    std::string text = ballScenarioWith("sex: male ", "sex: female ");
    for (const auto& [from, to] : {std::pair<std::string, std::string>{"mass: 73.0 ", "mass: 50.0 "}, {"stature: 1.741 ", "stature: 1.52 "}}) {
        const std::size_t at = text.find(from);
        ASSERT_NE(at, std::string::npos) << from;
        text.replace(at, from.size(), to);
    }
    const std::string file = write("small.yaml", text);
    const RunResult r = run("simulate " + file + " --out " + (dir_ / "out").string());
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    for (const char* f : {"small.yaml", "segment 'middle_distal'", "mm inside the object"}) {
        EXPECT_NE(r.err.find(f), std::string::npos) << "missing '" << f << "' in " << r.err;
    }
    EXPECT_FALSE(fs::exists(dir_ / "out"));
}

// A goal on the ball's surface but on top of it, where the palm covers the ball: the index finger
// cannot get there from the grasp pose. One line naming the goal, exit 2, no output folder.
TEST_F(SimulateCommand, GoalOutOfReachIsRefused) {
    extraFiles_ = 1;
    const std::string file = write("far.yaml", ballScenarioWith("index_tip: [0.0199, 0.0001, -0.0403]", "index_tip: [0, 0.045, 0]"));
    const RunResult r = run("simulate " + file + " --out " + (dir_ / "out").string());
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    for (const char* f : {"far.yaml", "goal 'index_tip' is out of reach", "mm from it"}) {
        EXPECT_NE(r.err.find(f), std::string::npos) << "missing '" << f << "' in " << r.err;
    }
    EXPECT_FALSE(fs::exists(dir_ / "out"));
}
