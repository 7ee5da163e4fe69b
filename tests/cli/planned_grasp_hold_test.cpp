// The issue's old failure, end to end: the thesis ball in a 50 kg, 1.52 m woman's hand, given as
// `grasp: {type: power-sphere}`, is planned when simulate loads it and is held. Oracle: the
// physical criterion of docs/planning.md: after settling, the ball drifts < 5 mm over 2 s in full
// compliant contact under gravity, and no segment overlaps it at t = 0 (the plan's check).

#include "cli_process.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

using graspsim::testing::RunResult;
class PlannedGraspHold : public graspsim::testing::CliProcess {
protected:
    // Simulates the scenario `text` (its grasp planned as simulate loads it, its own duration) and
    // expects its object held, drifting less than `drift` (m) after settling.
    void expectHeld(const std::string& text, double drift) {
        const std::string scenario = write("planned.yaml", text);
        extraFiles_ = 1;
        const RunResult r = run("simulate " + scenario + " -q --out " + (dir_ / "out").string());
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const nlohmann::json summary = nlohmann::json::parse(graspsim::testing::slurp(dir_ / "out" / "summary.json"));
        EXPECT_TRUE(summary["held"].get<bool>());
        EXPECT_LT(summary["object_displacement_m"].get<double>(), drift);
    }
};

TEST_F(PlannedGraspHold, TheSmallWomanHoldsTheThesisBallInAPlannedClutch) {
    expectHeld(R"(name: small-woman-ball
subject: {sex: female, mass: 50, stature: 1.52}
object: {shape: sphere, mass: 0.2, radius: 0.045}
grasp: {type: power-sphere}
controller: {kp: 10}
)", 0.005);
}

// The cells the approximation did not engage on (docs/planning.md, the study): the 100 kg, 1.90 m
// man's planned power sphere (the passive springs took his middle finger's whole press) and
// power cylinder (four fingers pushed the released cylinder off the little one). Oracle: the
// grasp switch engages only once every goal finger touches the object after the release
// (simulation/grasp_switch.cpp), which it checks on the simulated contacts, not on the plan.
TEST_F(PlannedGraspHold, TheTallHeavyMansPlannedSphereAndCylinderEngageTheApproximation) {
    const char* objects[] = {"{shape: sphere, mass: 0.2, radius: 0.045}\ngrasp: {type: power-sphere}\n",
                             "{shape: cylinder, mass: 0.2, radius: 0.02, length: 0.15}\ngrasp: {type: power-cylinder}\n"};
    int k = 0;
    for (const char* object : objects) {
        const std::string name = "grasp" + std::to_string(k++);
        const std::string scenario = write(name + ".yaml", "name: " + name +
                                                               "\nsubject: {sex: male, mass: 100, stature: 1.90}\nobject: " +
                                                               object + "controller: {kp: 10}\n");
        const RunResult r = run("simulate " + scenario + " -q --mode approx --duration 1.5 --out " + (dir_ / name).string());
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const nlohmann::json summary = nlohmann::json::parse(graspsim::testing::slurp(dir_ / name / "summary.json"));
        EXPECT_TRUE(summary["engaged"].get<bool>()) << object;
    }
}

// A flat ellipsoid (semi-axes 70, 4 and 35 mm: thin along y of its frame) in a pinch planned on
// load holds: the physical criterion of docs/planning.md, here held and a drift under 2 mm over
// 2 s after settling (0.72 mm measured). Before the planner started an ellipsoid turned like a box
// (thinnest axis along the squeeze), it started as labelled and its plan was refused ("the
// thumb_tip cannot press its goal").
TEST_F(PlannedGraspHold, APlannedPinchOfAFlatEllipsoidHolds) {
    expectHeld(R"(name: flat-ellipsoid
object: {shape: ellipsoid, mass: 0.1, semi_axes: [0.07, 0.004, 0.035]}
grasp: {type: pinch}
)", 0.002);
}

// A phone-sized box (70 x 140 x 8 mm, 100 g) in a lateral pinch planned on load holds, as the
// ellipsoid of its half-lengths does (drift 0.63 mm): held, and a drift under 2 mm over 2 s after
// settling (0.80 mm measured, the thumb, the index's middle and distal phalanges each pressing
// about 0.9 N). Before, its plan was refused in every labelling ("the index_middle_radial pad ends
// 8.32 mm from the surface"): from the template's start the optimizer stopped with both pads on
// one of the box's edges. Thin along x and y: LateralPinch.APhoneSizedBoxIsPinchedAcross...
TEST_F(PlannedGraspHold, APlannedLateralPinchOfAPhoneSizedBoxHolds) {
    expectHeld(R"(name: flat-box
object: {shape: box, mass: 0.1, size: [0.07, 0.14, 0.008]}
grasp: {type: lateral}
)", 0.002);
}
