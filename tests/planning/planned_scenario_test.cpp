// Scenarios that ask for a grasp type: read, planned when loaded, and written back as complete
// scenarios. Oracle: the planned scenario's goals lie on the object's surface (ObjectSpec's
// closed-form distance) and the written text reads back to the same pose and goals.

#include "graspsim/planning/planned_scenario.h"

#include "graspsim/error.h"
#include "graspsim/scenario/scenario_file.h"
#include "graspsim/scenario/scenario_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <sstream>

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

// The planner rounds to 0.1 deg and 0.1 mm; its file shows those numbers as written decimals
// (16.4, 0.1805; not 16.400000000000002, 0.18050000000000002) and reads back as the plan, bit for
// bit. Oracles: the reader, and the text: a pose angle or orientation written with at most one
// decimal, a length in at most 7 characters (-0.1805, 3e-04). The lateral pinch of a key: every
// kind of number (pose, orientation, position, goals, its added end-effector, a thin press).
TEST(PlannedScenario, ThePlansFileReadsBackBitForBit) {
    const scenario::Scenario base = scenario::parseScenario(
        "name: key\nobject: {shape: box, mass: 0.02, size: [0.05, 0.02, 0.003]}\ngrasp: {type: lateral}\n", "key.yaml");
    const planning::GraspPlan plan = planning::planGrasp(planning::makeGraspRequest(base, planning::GraspType::Lateral));
    const scenario::Scenario planned = planning::applyPlan(base, plan);
    const std::string text = planning::formatPlannedScenario(planned, plan);
    const scenario::Scenario back = scenario::parseScenario(text, "planned.yaml");
    ASSERT_EQ(back.graspPose.size(), planned.graspPose.size());
    for (const auto& [joint, angle] : planned.graspPose) EXPECT_EQ(back.graspPose.at(joint), angle) << joint;
    for (const auto& [effector, goal] : planned.goals) {
        for (int i = 0; i < 3; ++i) EXPECT_EQ(back.goals.at(effector)[i], goal[i]) << effector;
    }
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(back.object.position[i], planned.object.position[i]);
        EXPECT_EQ(back.object.orientation[i], planned.object.orientation[i]);
        EXPECT_EQ(back.object.position[i], plan.X_GO.p()[i]);
    }
    EXPECT_EQ(back.controller.pressDepth, planned.controller.pressDepth);
    ASSERT_EQ(back.bodyOptions.segmentPoints.size(), 1u);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(back.bodyOptions.segmentPoints[0].p_B[i], plan.segmentPoints[0].p_B[i]);

    const std::regex angle(R"(^  [a-z_]+: -?[0-9]+(\.[0-9])?$)"), number(R"(-?[0-9][0-9.e+-]*)");
    const std::regex orientation(R"(\n  orientation: \[-?[0-9]+(\.[0-9])?, -?[0-9]+(\.[0-9])?, -?[0-9]+(\.[0-9])?\]  # deg\n)");
    EXPECT_TRUE(std::regex_search(text, orientation)) << text;
    const size_t pose = text.find("\ngrasp_pose:"), poseEnd = text.find("\n\n", pose + 1);
    std::istringstream poseLines(text.substr(pose + 1, poseEnd - pose - 1));
    std::string line;
    std::getline(poseLines, line);  // the section's key
    while (std::getline(poseLines, line)) EXPECT_TRUE(std::regex_match(line, angle)) << line;
    for (const char* key : {"  position: [", "  index_middle_radial: [", "  thumb_tip: [", "point: ["}) {
        const size_t at = text.find(key);
        ASSERT_NE(at, std::string::npos) << key;
        const std::string list = text.substr(at + std::string(key).size(), text.find(']', at) - at - std::string(key).size());
        for (auto it = std::sregex_iterator(list.begin(), list.end(), number); it != std::sregex_iterator(); ++it) {
            EXPECT_LE(it->str().size(), 7u) << key << list;
        }
    }
}
