#include "graspsim/simulation/rigid_stepping.h"

#include "graspsim/contact/rigid_impulse_solver.h"
#include "graspsim/error.h"
#include "graspsim/system/silenced_stdout.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace graspsim::simulation {

namespace {

// Times closer than this (s) are the same instant: sums of steps carry rounding errors.
constexpr double kTimeEpsilon = 1e-12;

}  // namespace

RigidStepper::RigidStepper(const GraspScene& scene, double stepSize)
    : scene_(scene), stepper_(scene.getSystem()), stepSize_(stepSize) {
    if (scene.getContactModel() != ContactModel::Rigid) throw InputError("rigid stepping: the scene was built for compliant contact");
    if (!(std::isfinite(stepSize) && stepSize > 0)) throw InputError("rigid stepping: step size (" + std::to_string(stepSize) + " s) must be > 0");
    // Simbody 3.7's default PLUS solver sticks at any pull (rigid_contact.h). PGS it is, as
    // Simbody's PGSImpulseSolver computes it but without Debian's debug work (rigid_impulse_solver.h).
    stepper_.setImpulseSolverType(SimTK::SemiExplicitEulerTimeStepper::PGS);
    stepper_.setImpulseSolver(new contact::RigidImpulseSolver());
    stepper_.setConstraintTolerance(kRigidContactTolerance);
}

void RigidStepper::initialize(const SimTK::State& initial, std::optional<double> nextIk) {
    SimTK::State state = initial;
    scene_.getImpedance().setStepSize(state, stepSize_);
    stepper_.initialize(state);
    nextIk_ = nextIk.value_or(initial.getTime() + scene_.getScenario().controller.ikInterval);
}

void RigidStepper::stepTo(double t) {
    system::SilencedStdout quiet;
    while (stepper_.getTime() < t - kTimeEpsilon) {
        double end = std::min({stepper_.getTime() + stepSize_, t, nextIk_});
        // Never leave a sliver of a step before a target: stretch to it if it is that close.
        if (std::min(t, nextIk_) - end < 0.01 * stepSize_) end = std::min(t, nextIk_);
        takeStep(end);
        if (std::abs(stepper_.getTime() - nextIk_) < kTimeEpsilon) {
            SimTK::State& s = stepper_.updState();
            scene_.getSystem().realize(s, SimTK::Stage::Position);
            scene_.getController().updateTargets(s);
            nextIk_ += scene_.getScenario().controller.ikInterval;
        }
    }
}

void RigidStepper::takeStep(double t) {
    SimTK::State& s = stepper_.updState();
    const double h = t - s.getTime();
    if (std::abs(scene_.getImpedance().getStepSize(s) - h) > kTimeEpsilon) scene_.getImpedance().setStepSize(s, h);
    stepper_.stepTo(t);
    ++steps_;
    scene_.getImpedance().updateConstraintForces(stepper_.updState());
}

void RigidStepper::releaseObject() {
    SimTK::State released = stepper_.getState();
    scene_.releaseObject(released);
    stepper_.initialize(released);  // a lock change is an Instance-stage change
}

}  // namespace graspsim::simulation
