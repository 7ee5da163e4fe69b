// Implicit joint impedance inside Simbody's SemiExplicitEulerTimeStepper, on the thesis arm and
// hand alone (gravity, passive springs, dampers and limit stops; no contact).
// Oracle: a second, independent method, the same stepper with no correction at a step small
// enough for explicit stability (2 microseconds), and the energy balance (no input, so the
// mechanical energy may only fall).

#include "graspsim/system/implicit_joint_impedance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "graspsim/model/body_model.h"
#include "graspsim/system/multibody_model.h"
#include "graspsim/system/silenced_stdout.h"

namespace graspsim::system {
namespace {

// The arm starts 0.2 rad from zero pose in every joint, every joint turning at 1 rad/s: the
// fingers' springs and dampers (and stops where 0.2 rad is out of range) take their speed out
// within microseconds, the arm swings under gravity against its dampers.
struct ArmScene {
    MultibodyModel model{model::buildBodyModel([] {
        model::BuildOptions o;
        o.preset = model::Preset::Thesis;
        return o;
    }())};
    ImplicitJointImpedance impedance;

    ArmScene() {
        std::vector<JointImpedance> joints;
        for (const std::string& name : model.getJointNames()) {
            const model::Joint& j = *model.getDescription().findJoint(name);
            joints.push_back({model.getMobilizedBody(j.child).getMobilizedBodyIndex(), j.stiffness, j.damping,
                              model.getPassiveJointForces(name).getStop()});
        }
        impedance = ImplicitJointImpedance(model.updForces(), model.getMatter(), joints);
        model.realizeTopology();
    }
};

struct SteppedRun {
    SimTK::Vector q;           // at the end
    double maxEnergyRise = 0;  // J, largest step-to-step increase of the mechanical energy
    double energyDrop = 0;     // J, E(0) - E(end)
};

SteppedRun simulate(ArmScene& scene, double h, bool implicit, double duration) {
    SimTK::State state = scene.model.getSystem().getDefaultState();
    state.updQ() = 0.2;
    state.updU() = 1.0;
    scene.impedance.setStepSize(state, implicit ? h : 0);
    SimTK::SemiExplicitEulerTimeStepper stepper(scene.model.getSystem());
    stepper.setImpulseSolverType(SimTK::SemiExplicitEulerTimeStepper::PGS);
    stepper.initialize(state);
    const auto energy = [&](const SimTK::State& s) {
        scene.model.getSystem().realize(s, SimTK::Stage::Dynamics);
        return scene.model.calcMechanicalEnergy(s);
    };
    SteppedRun run;
    const double e0 = energy(stepper.getState());
    double last = e0;
    const long n = std::lround(duration / h);
    SilencedStdout quiet;
    for (long k = 1; k <= n; ++k) {
        stepper.stepTo(k * h);
        const double e = energy(stepper.getState());
        run.maxEnergyRise = std::max(run.maxEnergyRise, e - last);
        last = e;
    }
    run.q = stepper.getState().getQ();
    run.energyDrop = e0 - last;
    return run;
}

double maxDifference(const SimTK::Vector& a, const SimTK::Vector& b) {
    double worst = 0;
    for (int i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(a[i] - b[i]));
    return worst;
}

TEST(ImplicitJointImpedance, AppliesNothingWithoutAStepSize) {
    ArmScene scene;
    SimTK::State state = scene.model.getSystem().getDefaultState();
    state.updU() = 0.3;  // moving, so that the dampers act
    scene.model.getSystem().realize(state, SimTK::Stage::Velocity);
    EXPECT_EQ(SimTK::max(SimTK::abs(scene.impedance.calcCorrection(state))), 0.0);
    scene.impedance.setStepSize(state, 1e-3);
    scene.model.getSystem().realize(state, SimTK::Stage::Velocity);
    EXPECT_GT(SimTK::max(SimTK::abs(scene.impedance.calcCorrection(state))), 0.0);
}

TEST(ImplicitJointImpedance, ConvergesToTinyExplicitSteps) {
    const double duration = 0.05;  // s
    ArmScene scene;
    const SteppedRun reference = simulate(scene, 2e-6, false, duration);
    const SteppedRun fine = simulate(scene, 1e-4, true, duration);
    const SteppedRun coarse = simulate(scene, 1e-3, true, duration);
    double motion = 0;  // how far the joints went: the scale of the errors below
    for (int i = 0; i < reference.q.size(); ++i) motion = std::max(motion, std::abs(reference.q[i] - 0.2));
    const double errorFine = maxDifference(fine.q, reference.q);
    const double errorCoarse = maxDifference(coarse.q, reference.q);
    std::printf("largest joint motion %.4g rad; error at h = 1e-4 s: %.3g rad, at 1e-3 s: %.3g rad\n", motion,
                errorFine, errorCoarse);
    // First order: a tenth of the step, about a tenth of the error (a factor 5 allows for the
    // reference's own O(2e-6) error and higher-order terms); and small against the motion.
    EXPECT_LT(errorFine, errorCoarse / 5);
    EXPECT_LT(errorFine, 0.01 * motion);
}

TEST(ImplicitJointImpedance, EnergyNeverRises) {
    ArmScene scene;
    for (double h : {1e-4, 1e-3}) {
        const SteppedRun run = simulate(scene, h, true, 0.1);
        std::printf("h = %g s: energy dropped %.4g J, largest step rise %.3g J\n", h, run.energyDrop,
                    run.maxEnergyRise);
        EXPECT_GT(run.energyDrop, 0) << h;
        EXPECT_LE(run.maxEnergyRise, 1e-6 * run.energyDrop) << h;
    }
}

// updateConstraintForces() on the stepper's end-of-step state adds the correction to that
// realization instead of discarding it. Oracle: a fresh realization of the same state.
TEST(ImplicitJointImpedance, CompletesTheStepperRealizationAsAFreshOneWould) {
    ArmScene scene;
    const SimTK::MultibodySystem& system = scene.model.getSystem();
    SimTK::State initial = system.getDefaultState();
    initial.updQ() = 0.2;
    initial.updU() = 1.0;
    scene.impedance.setStepSize(initial, 1e-3);
    SimTK::SemiExplicitEulerTimeStepper stepper(system);
    stepper.setImpulseSolverType(SimTK::SemiExplicitEulerTimeStepper::PGS);
    stepper.initialize(initial);
    SilencedStdout quiet;
    stepper.stepTo(1e-3);
    scene.impedance.updateConstraintForces(stepper.updState());
    stepper.stepTo(2e-3);
    SimTK::State& state = stepper.updState();
    const SimTK::Vector without = system.getMobilityForces(state, SimTK::Stage::Dynamics);
    scene.impedance.updateConstraintForces(state);
    ASSERT_GE(state.getSystemStage(), SimTK::Stage::Dynamics);  // nothing left to realize
    const SimTK::Vector completed = system.getMobilityForces(state, SimTK::Stage::Dynamics);
    SimTK::State fresh = state;
    fresh.invalidateAllCacheAtOrAbove(SimTK::Stage::Dynamics);
    system.realize(fresh, SimTK::Stage::Dynamics);
    const SimTK::Vector& expected = system.getMobilityForces(fresh, SimTK::Stage::Dynamics);
    const double scale = SimTK::max(SimTK::abs(expected));
    EXPECT_GT(maxDifference(completed, without), 1e-3 * scale);  // the correction is there
    EXPECT_LE(maxDifference(completed, expected), 1e-12 * scale);
}

}  // namespace
}  // namespace graspsim::system
