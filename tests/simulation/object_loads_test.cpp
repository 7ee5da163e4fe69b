// The run's external loads as the grasp switch reads them (ObjectLoads::findWrenchAt, the carried
// load of the compliance trigger). Oracle: the force elements themselves, the second method: the
// forces Simbody applies on the object at Stage::Dynamics, less its weight, with the hand open
// (nothing touches the object), before, inside and after the loads' windows.
#include "graspsim/simulation/grasp_experiment.h"
#include "graspsim/scenario/scenario_file.h"

#include <gtest/gtest.h>

using namespace graspsim;

TEST(ObjectLoads, TheWrenchIsWhatTheElementsApply) {
    const scenario::Scenario s = scenario::findBuiltinScenario("ball-clutch");
    for (const bool torque : {false, true}) {
        SCOPED_TRACE(torque ? "torque ramp" : "force ramp");
        simulation::SimulationOptions options;
        options.perturbation = "f1";  // (0, -9.5, 0) N from 1.5 s to 2.5 s
        options.loadRamp = simulation::LoadRampSpec{SimTK::UnitVec3(0.3, 0, 1), torque, 2.0, 0.05, 0.2};
        simulation::GraspExperiment experiment(s, options);
        SimTK::State state = experiment.makeInitialState();
        const simulation::GraspScene& scene = experiment.getScene();
        const SimTK::MobilizedBody& object = scene.getObject();
        for (const double t : {1.0, 1.6, 2.0, 2.3, 2.6}) {
            SCOPED_TRACE(t);
            state.setTime(t);
            scene.getSystem().realize(state, SimTK::Stage::Dynamics);
            const SimTK::SpatialVec applied = scene.getSystem().getRigidBodyForces(state, SimTK::Stage::Dynamics)[object.getMobilizedBodyIndex()];
            const SimTK::Vec3 weight = object.getBodyMass(state) * scene.getModel().getGravity().getGravityVector(state);
            const SimTK::SpatialVec wrench = experiment.getLoads().findWrenchAt(t);
            // The object's origin is its centre of mass: Simbody's moment about it is the loads'.
            EXPECT_LT((wrench[0] - applied[0]).norm(), 1e-12) << wrench[0] << " " << applied[0];
            EXPECT_LT((wrench[1] - (applied[1] - weight)).norm(), 1e-12) << wrench[1] << " " << applied[1] - weight;
        }
        // Closed form inside both windows: f1, and the ramp's 0.05 + 0.2 (t - 2) along its direction.
        const SimTK::SpatialVec at = experiment.getLoads().findWrenchAt(2.3);
        const SimTK::Vec3 ramp = (0.05 + 0.2 * 0.3) * SimTK::Vec3(SimTK::UnitVec3(0.3, 0, 1));
        EXPECT_LT((at[torque ? 0 : 1] - ramp - (torque ? SimTK::Vec3(0) : SimTK::Vec3(0, -9.5, 0))).norm(), 1e-12);
        if (torque) EXPECT_LT((at[1] - SimTK::Vec3(0, -9.5, 0)).norm(), 1e-12);
    }
}
