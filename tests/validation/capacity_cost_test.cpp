// The bench's capacity table (validation/capacity_cost.h). Oracles: the ramp's simulated span
// against a second ramp of the same scene (deterministic: it ends at the same drop), and the
// text's cells.

#include "graspsim/validation/capacity_cost.h"

#include "graspsim/capacity/grasp_capacity.h"
#include "graspsim/scenario/scenario_file.h"

#include <gtest/gtest.h>

namespace graspsim::validation {
namespace {

TEST(CapacityCost, TimesTheRampToItsDropAndTheThreeSecondRun) {
    const scenario::Scenario s = scenario::findBuiltinScenario("phone-pinch");
    const CapacityCost row = measureCapacityCost(s, simulation::SimulationMode::Full, simulation::IntegratorChoice::LinearlyImplicit, true);
    simulation::SimulationOptions options;
    options.integrator = simulation::IntegratorChoice::LinearlyImplicit;
    const capacity::GraspCapacity again = capacity::measureGraspCapacityRamp(s, options, capacity::GraspCapacityRequest{});
    ASSERT_TRUE(again.trace.figures.dropped);
    EXPECT_TRUE(row.failure.empty()) << row.failure;
    // The ramp stops at the drop: its last sample is the drop's (the phone drops within 1 s of load).
    EXPECT_NEAR(row.rampSimTime, again.trace.samples.back().time, 1e-12);
    EXPECT_GE(row.rampSimTime, again.trace.figures.dropTime - 1e-12);
    EXPECT_GT(row.rampWall, 0);
    EXPECT_GT(row.simulationWall, 0);
    EXPECT_GT(row.allWall, 0);
}

TEST(CapacityCost, TableStatesTheRatio) {
    CapacityCost row;
    row.scenario = "ball-clutch";
    row.mode = simulation::SimulationMode::Approx;
    row.integrator = simulation::IntegratorChoice::LinearlyImplicit;
    row.rampWall = 0.5;
    row.rampSimTime = 5.1;
    row.simulationWall = 0.25;
    row.allWall = 1.8;
    const std::string text = formatCapacityCostTable({row});
    const std::string line = text.substr(text.find("ball-clutch"));
    EXPECT_NE(line.find("approx"), std::string::npos) << text;
    EXPECT_NE(line.find("implicit"), std::string::npos) << text;
    EXPECT_NE(line.find("(5.10)"), std::string::npos) << text;
    EXPECT_NE(line.find("2.00"), std::string::npos) << text;  // ramp / simulation
    EXPECT_NE(line.find("0.200"), std::string::npos) << text;  // per direction: 1.8 / 9
    EXPECT_NE(line.find("0.80"), std::string::npos) << text;   // per direction / simulation
    row.allWall = 0;
    const std::string untimed = formatCapacityCostTable({row});
    EXPECT_EQ(untimed.find("0.200"), std::string::npos) << untimed;
}

}  // namespace
}  // namespace graspsim::validation
