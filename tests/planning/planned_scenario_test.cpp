// Scenarios that ask for a grasp type: read, planned when loaded, and written back as complete
// scenarios. Oracle: the planned scenario's goals lie on the object's surface (ObjectSpec's
// closed-form distance) and the written text reads back to the same pose and goals.

#include "graspsim/planning/planned_scenario.h"

#include "graspsim/error.h"
#include "graspsim/scenario/scenario_file.h"
#include "graspsim/scenario/scenario_writer.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace graspsim;

namespace {

const char* kPlannedBall = R"(name: small-woman-ball
subject: {sex: female, mass: 50, stature: 1.52}
object: {shape: sphere, mass: 0.2, radius: 0.045}
grasp: {type: power-sphere}
)";

}  // namespace

TEST(PlannedScenario, AGraspTypeIsPlannedWhenTheScenarioIsCompleted) {
    scenario::Scenario s = scenario::parseScenario(kPlannedBall, "ball.yaml");
    EXPECT_EQ(s.graspType, "power-sphere");
    EXPECT_TRUE(s.graspPose.empty());
    planning::completeScenario(s);
    EXPECT_TRUE(s.graspType.empty());
    EXPECT_EQ(s.goals.size(), 5u);
    EXPECT_FALSE(s.graspPose.empty());
    for (const auto& [effector, goal] : s.goals) EXPECT_LT(std::abs(s.object.calcSurfaceDistance(goal)), 2e-4) << effector;
    EXPECT_EQ(s.controller.kp, 10.0);  // no gain in the file: the plan's (a five-finger clutch, as ball-clutch.yaml)
    EXPECT_EQ(s.contact.capsuleContact, contact::CapsuleContact::Deepest);  // fingertip pads: the file's rule
    // the completed scenario is an ordinary one: written and read back, the same pose and goals
    const scenario::Scenario reread = scenario::parseScenario(scenario::formatScenarioYaml(s), "resolved.yaml");
    ASSERT_EQ(reread.graspPose.size(), s.graspPose.size());
    for (const auto& [joint, angle] : s.graspPose) EXPECT_NEAR(reread.graspPose.at(joint), angle, 1e-12) << joint;
    for (const auto& [effector, goal] : s.goals) EXPECT_NEAR(reread.goals.at(effector)[0], goal[0], 1e-15) << effector;
}

TEST(PlannedScenario, AGainGivenInTheFileStays) {
    scenario::Scenario s = scenario::parseScenario(std::string(kPlannedBall) + "controller: {kp: 7}\n", "ball.yaml");
    planning::completeScenario(s);
    EXPECT_EQ(s.controller.kp, 7.0);
}

// A key in a lateral pinch with no controller section: the default 2 mm press does not fit its
// 3 mm thickness, and the plan sets both the press (below the half-thickness) and its gain; the
// index middle phalanx lies flat on the key, so the plan presses capsules at their ends.
TEST(PlannedScenario, AThinObjectTakesThePlansPressAndGain) {
    scenario::Scenario s = scenario::parseScenario(
        "name: key\nobject: {shape: box, mass: 0.02, size: [0.05, 0.02, 0.003]}\ngrasp: {type: lateral}\n", "key.yaml");
    planning::completeScenario(s);
    EXPECT_EQ(s.controller.kp, 2.0);
    EXPECT_GT(s.controller.pressDepth, 0);
    EXPECT_LT(s.controller.pressDepth, 0.0015);  // the reader's rule: below the half-thickness
    EXPECT_EQ(s.contact.capsuleContact, contact::CapsuleContact::Ends);
}

TEST(PlannedScenario, AScenarioWithAPoseIsLeftAsItIs) {
    scenario::Scenario s = scenario::findBuiltinScenario("ball-clutch");
    const scenario::Scenario before = s;
    planning::completeScenario(s);
    EXPECT_EQ(s.graspPose, before.graspPose);
    EXPECT_EQ(s.object.position, before.object.position);
}

TEST(PlannedScenario, AGraspTypeWithAPoseOrPlacementIsRefused) {
    const std::string base = kPlannedBall;
    for (const std::string& extra : {std::string("grasp_pose: {elbow_flexion: 90}\n"),
                                     std::string("goals: {index_tip: [0.045, 0, 0]}\n")}) {
        EXPECT_THROW(scenario::parseScenario(base + extra, "ball.yaml"), InputError) << extra;
    }
    std::string placed = base;
    placed.replace(placed.find("radius: 0.045}"), 14, "radius: 0.045, position: [0.4, -0.2, 0]}");
    try {
        scenario::parseScenario(placed, "ball.yaml");
        FAIL() << "accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("object.position"), std::string::npos) << e.what();
    }
}

TEST(PlannedScenario, AnUnknownGraspTypeNamesTheFileAndField) {
    std::string text = kPlannedBall;
    text.replace(text.find("power-sphere"), 12, "power_sphere");
    scenario::Scenario s = scenario::parseScenario(text, "ball.yaml");
    try {
        planning::completeScenario(s);
        FAIL() << "planned";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("ball.yaml: field 'grasp.type' value 'power_sphere'"), std::string::npos) << e.what();
    }
}
