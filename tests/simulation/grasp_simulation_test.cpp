// Full-contact grasp simulations of the thesis experiments, checked against conservation laws:
// a held object stays put, and at equilibrium the contact forces balance gravity plus the
// perturbation (Newton's first law on the object).

#include "graspsim/simulation/grasp_simulation.h"

#include "graspsim/error.h"
#include "graspsim/scenario/scenario_file.h"

#include <gtest/gtest.h>

using namespace graspsim;

namespace {

SimTK::Vec3 sumContactForceOnObject(const simulation::ContactSample& sample) {
    SimTK::Vec3 F(0);
    for (const contact::ContactReport& c : sample.contacts) {
        // The object is surface b of every pair: it gets +f_n n and the friction force.
        F += c.normalForce * SimTK::Vec3(c.n_G) + c.frictionForce_G;
    }
    return F;
}

double massOf(const scenario::Scenario& s) { return s.object.mass; }

class HoldWithoutPerturbation : public ::testing::TestWithParam<const char*> {};

}  // namespace

// Issue oracle: held against gravity for 2 s after the grasp settles, drift under 5 mm.
TEST_P(HoldWithoutPerturbation, ObjectDriftsLessThanFiveMillimetres) {
    const scenario::Scenario s = scenario::findBuiltinScenario(GetParam());
    simulation::SimulationOptions options;
    options.duration = s.simulation.settleTime + 2.0;
    const simulation::SimulationResult r = simulation::runGraspSimulation(s, options);
    ASSERT_TRUE(r.summary.complete) << r.summary.failure;
    EXPECT_TRUE(r.summary.held);
    EXPECT_LT(r.summary.objectDisplacement, 0.005);
    // Several hand bodies really carry the object.
    EXPECT_GE(r.contacts.back().contacts.size(), 2u);
}

INSTANTIATE_TEST_SUITE_P(Thesis, HoldWithoutPerturbation, ::testing::Values("ball-clutch", "phone-pinch"));

// Oracle: at equilibrium the summed contact forces on the object equal -(m g + f_perturbation).
TEST(GraspSimulation, ContactForcesBalanceGravityAndPerturbation) {
    const scenario::Scenario s = scenario::findBuiltinScenario("ball-clutch");
    simulation::SimulationOptions options;
    options.perturbation = "f2";
    const scenario::Perturbation& f2 = *s.findPerturbation("f2");
    options.duration = f2.start + 0.8 * f2.duration;  // well inside the window, after it settled
    const simulation::SimulationResult r = simulation::runGraspSimulation(s, options);
    ASSERT_TRUE(r.summary.complete) << r.summary.failure;
    const SimTK::Vec3 g(s.world.gravity[0], s.world.gravity[1], s.world.gravity[2]);
    const SimTK::Vec3 load = massOf(s) * g + SimTK::Vec3(f2.force[0], f2.force[1], f2.force[2]);
    const SimTK::Vec3 contact = sumContactForceOnObject(r.contacts.back());
    EXPECT_LT((contact + load).norm(), 0.01 * load.norm()) << "contact " << contact << " load " << load;
}

TEST(GraspSimulation, UnknownPerturbationIsRejectedBeforeSimulating) {
    const scenario::Scenario s = scenario::findBuiltinScenario("phone-pinch");
    simulation::SimulationOptions options;
    options.perturbation = "f9";
    EXPECT_THROW(simulation::runGraspSimulation(s, options), InputError);
}
