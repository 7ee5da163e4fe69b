// The planner's reach test is the set-up check's: for the grasp the check used to refuse (the
// reference woman's power sphere, little finger 3.2 mm from its pressed goal), the planner's
// numbers per goal (calcGoalReach through calcPlanDiagnostics) equal what the simulation's
// set-up check measures on the planned scenario (a second, independent path: GraspScene, its
// controller and IK on the full system with the object), and the plan passes the check.

#include "graspsim/planning/grasp_planner.h"
#include "graspsim/planning/planned_scenario.h"
#include "graspsim/scenario/scenario_file.h"
#include "graspsim/simulation/setup_check.h"

#include <gtest/gtest.h>

#include <iostream>

using namespace graspsim;

namespace {

void expectSameReach(const char* text, planning::GraspType type) {
    const scenario::Scenario base = scenario::parseScenario(text, "planned.yaml");
    const planning::GraspRequest request = planning::makeGraspRequest(base, type);
    const planning::GraspPlan plan = planning::planGrasp(request);
    scenario::Scenario planned = planning::applyPlan(base, plan);
    planned.graspType.clear();  // planned: the scenario now has its pose, goals and placement
    const simulation::SetupCheck check = simulation::checkScenarioSetup(planned, simulation::SimulationOptions{});
    ASSERT_EQ(check.goals.size(), plan.diagnostics.goals.size());
    for (const simulation::GoalReach& measured : check.goals) {
        bool found = false;
        for (const planning::GoalCheck& g : plan.diagnostics.goals) {
            if (g.effector != measured.endEffector) continue;
            found = true;
            std::cout << g.effector << ": planner " << g.reachShortfall * 1000 << " mm, set-up check "
                      << measured.distance * 1000 << " mm from the pressed goal; pad " << g.commandedPress * 1000
                      << " mm inside\n";
            EXPECT_NEAR(g.reachShortfall, measured.distance, 1e-5) << g.effector;
            EXPECT_LE(g.reachShortfall, simulation::kGoalReachTolerance) << g.effector;
            EXPECT_GE(g.commandedPress, planning::PlanTolerances{}.minCommandedPress) << g.effector;
        }
        EXPECT_TRUE(found) << measured.endEffector;
    }
}

}  // namespace

TEST(GoalReach, ThePlannersReachIsTheSetupChecksAndThePlanPassesIt) {
    EXPECT_DOUBLE_EQ(planning::PlanTolerances{}.maxReachShortfall, simulation::kGoalReachTolerance);
    // the grasp the check refused before; every finger reaches its pressed goal
    expectSameReach("name: planned\nsubject: {sex: female}\nobject: {shape: sphere, mass: 0.2, radius: 0.045}\n"
                    "grasp: {type: power-sphere}\n", planning::GraspType::PowerSphere);
    // a thumb that stops short of its pressed goal (by about 2.5 mm), within the check's 3 mm
    expectSameReach("name: planned\nsubject: {sex: male, mass: 100, stature: 1.90}\n"
                    "object: {shape: cylinder, mass: 0.2, radius: 0.02, length: 0.15}\ngrasp: {type: power-cylinder}\n",
                    planning::GraspType::PowerCylinder);
}
