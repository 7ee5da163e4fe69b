// Rigid stepping of a grasp scene: what the loop guarantees (fixed steps landing on the output
// samples, options it refuses), on a short run. The physics is checked by the validation test
// contact_model_agreement_test.cpp and by tests/system/implicit_joint_impedance_test.cpp.

#include "graspsim/simulation/rigid_stepping.h"

#include "graspsim/error.h"
#include "graspsim/scenario/scenario_file.h"
#include "graspsim/simulation/grasp_simulation.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace graspsim;

TEST(RigidStepping, TakesFixedStepsAndLandsOnEverySample) {
    const scenario::Scenario s = scenario::findBuiltinScenario("ball-clutch");
    simulation::SimulationOptions options;
    options.contact = simulation::ContactModel::Rigid;
    options.duration = 0.05;
    const simulation::SimulationResult r = simulation::runGraspSimulation(s, options);
    ASSERT_TRUE(r.summary.complete) << r.summary.failure;
    EXPECT_EQ(r.summary.steps, std::lround(options.duration / simulation::kRigidStepSize));
    for (std::size_t k = 0; k < r.trajectory.size(); ++k)
        EXPECT_NEAR(r.trajectory[k].time, k * s.simulation.outputInterval, 1e-12);
    EXPECT_GE(r.contacts.back().contacts.size(), 2u);  // the fingers have closed on the ball
}

TEST(RigidStepping, RefusesApproxModeAndCompliantScenes) {
    const scenario::Scenario s = scenario::findBuiltinScenario("phone-pinch");
    simulation::SimulationOptions options;
    options.contact = simulation::ContactModel::Rigid;
    options.mode = simulation::SimulationMode::Approx;
    EXPECT_THROW(simulation::GraspScene(s, options), InputError);
    simulation::SimulationOptions compliant;
    const simulation::GraspScene scene(s, compliant);
    EXPECT_THROW(simulation::RigidStepper stepper(scene), InputError);
}
