// The bench's stepper table (validation/stepper_cost.h). Oracles: the row's counts against a
// second run of the same scenario on the same stepper (deterministic, so the same counts), the
// methods' own structure (ROS2 evaluates twice per step and iterates no Newton; CPodes's BDF
// iterates), and the text's cells.

#include "graspsim/validation/stepper_cost.h"

#include "graspsim/scenario/scenario_file.h"
#include "graspsim/simulation/grasp_simulation.h"

#include <gtest/gtest.h>

namespace graspsim::validation {
namespace {

constexpr double kDuration = 0.3;  // s: the fingers close and land on the ball

TEST(StepperCost, ImplicitRowCountsTheRunsStepsAndItsStructure) {
    const scenario::Scenario s = scenario::findBuiltinScenario("ball-clutch");
    const StepperCost row = measureFullContactStepper(s, simulation::IntegratorChoice::LinearlyImplicit, kDuration, 5);
    simulation::SimulationOptions options;
    options.duration = kDuration;
    options.integrator = simulation::IntegratorChoice::LinearlyImplicit;
    const simulation::SimulationSummary again = simulation::runGraspSimulation(s, options).summary;
    EXPECT_EQ(row.run, "full, implicit");
    EXPECT_NEAR(row.stepsPerSimSecond * kDuration, static_cast<double>(again.steps), 1e-6);
    EXPECT_NEAR(row.evaluationsPerSimSecond * kDuration, static_cast<double>(again.integratorStatistics.rhsEvaluations), 1e-6);
    EXPECT_GE(row.evaluationsPerSimSecond, 2 * row.stepsPerSimSecond);  // two stages per step
    EXPECT_GT(row.factorizationsPerSimSecond, 0);
    EXPECT_LE(row.factorizationsPerSimSecond, row.evaluationsPerSimSecond / 2);
    EXPECT_EQ(row.newtonPerSimSecond, 0);
    EXPECT_GE(row.linearSolveUs, 0);
    EXPECT_GT(row.dynamicsUs, row.contactUs);  // the evaluation includes the contact force
    EXPECT_GT(row.contactUs, 0);
    EXPECT_GT(row.stepUs, row.dynamicsUs);
}

TEST(StepperCost, CpodesRowHasNewtonIterationsAndNoLinearSolveClock) {
    const StepperCost row = measureFullContactStepper(scenario::findBuiltinScenario("ball-clutch"),
                                                      simulation::IntegratorChoice::SimbodyCpodes, kDuration, 5);
    EXPECT_EQ(row.run, "full, cpodes");
    EXPECT_GT(row.newtonPerSimSecond, row.stepsPerSimSecond);  // at least one iteration per step
    EXPECT_EQ(row.linearSolveUs, -1);
    EXPECT_GE(row.restartsPerSimSecond, 0);
}

// The held row times only the window after settle_time + warm-up: a run that ends before the
// window has nothing to time (0), one that reaches it a positive time, and no counts either way.
TEST(StepperCost, HeldRowTimesOnlyTheHeldWindow) {
    scenario::Scenario s = scenario::findBuiltinScenario("ball-clutch");
    s.simulation.settleTime = 0.2;
    const StepperCost row = measureHeldFullContact(s, simulation::IntegratorChoice::LinearlyImplicit, 0.05, 0.1);
    EXPECT_EQ(row.run, "full, implicit, held");
    EXPECT_GT(row.wallPerSimSecond, 0);
    EXPECT_EQ(row.stepsPerSimSecond, -1);
    EXPECT_EQ(row.evaluationsPerSimSecond, -1);
    const StepperCost none = measureHeldFullContact(s, simulation::IntegratorChoice::LinearlyImplicit, 0.05, 0.0);
    EXPECT_EQ(none.wallPerSimSecond, 0);
}

TEST(StepperCost, TableShowsUnknownsAsDashes) {
    StepperCost floor;
    floor.scenario = "ball-clutch";
    floor.run = "floor";
    floor.wallPerSimSecond = 0.0125;
    floor.evaluationsPerSimSecond = 210;
    const std::string text = formatStepperTable({floor});
    const std::string row = text.substr(text.find("ball-clutch"));
    EXPECT_NE(row.find("0.0125"), std::string::npos) << text;
    EXPECT_NE(row.find("210"), std::string::npos) << text;
    EXPECT_NE(row.find(" - "), std::string::npos) << text;
}

}  // namespace
}  // namespace graspsim::validation
