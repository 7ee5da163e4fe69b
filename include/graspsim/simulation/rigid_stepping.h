#pragma once
/// @file
/// Stepping a grasp scene with rigid contact: Simbody's SemiExplicitEulerTimeStepper (PGS
/// impulses, by contact::RigidImpulseSolver) at a fixed step, with everything that stepper does
/// not do itself.
///
/// The stepper takes exactly one step per stepTo() and has no event handling, so this loop
///  - takes steps of the fixed size h, shortened to land exactly on every time where an input
///    jumps or the controller acts (the caller's targets: output samples, the release, the
///    perturbation's start and end) and on every IK update;
///  - runs the IK grasp controller every ik_interval (GraspController::updateTargets(); the
///    targets are a Stage::Dynamics change, picked up by the next step);
///  - releases the object (an Instance-stage change) and re-initializes the stepper;
///  - tells the implicit joint impedance the size of each step and, after it, the step's
///    constraint forces (system/implicit_joint_impedance.h);
///  - silences fd 1 while stepping (system/silenced_stdout.h: Debian's Simbody prints a debug
///    trace at every step).
///
/// Stages: after stepTo() the state is realized to Stage::Dynamics and holds the last step's
/// multipliers (contact forces), as GraspScene::findContactReports() needs.
#include "graspsim/simulation/grasp_scene.h"

#include "graspsim/simbody.h"

#include <optional>

namespace graspsim::simulation {

/// The rigid model's fixed step (s). With the joint impedance implicit, the step is limited by
/// accuracy, not stability: 1 ms is a fifth of the fingers' impedance time constant (PD kd / kp
/// = 5 ms in ball-clutch) and a tenth of the IK interval. Against steps ten times shorter, the
/// thesis experiments' objects stay within 0.25 mm and 0.4 degrees over 1.5 s (docs/performance.md,
/// "Rigid contact").
constexpr double kRigidStepSize = 1e-3;

/// Gap (m) within which a rigid contact counts as touching (proximal) for the next step: the
/// stepper's constraint tolerance. Small against the compliant model's millimetre-scale
/// penetrations. A fingertip closing at 0.1 m/s moves 0.1 mm per step, so a contact may close
/// inside a step; the stepper's position projection then pushes it out over the next steps
/// (the thesis experiments' deepest rigid penetration is 0.18 mm at 1 ms steps, 0.01 mm at 0.1 ms).
constexpr double kRigidContactTolerance = 1e-5;

/// Fixed-step rigid-contact stepping of one GraspScene built with ContactModel::Rigid.
class RigidStepper {
public:
    /// @throws graspsim::InputError if the scene was not built for rigid contact or h <= 0.
    RigidStepper(const GraspScene& scene, double stepSize = kRigidStepSize);

    /// Starts at `initial` (GraspScene::makeInitialState()); the next IK update is one
    /// ik_interval later (makeInitialState() ran the first), or at `nextIk` (s) when given: a
    /// run resumed from a state another stepper reached (getNextIkTime()).
    void initialize(const SimTK::State& initial, std::optional<double> nextIk = std::nullopt);
    /// Steps to time t (s) >= the current time, landing on it exactly.
    void stepTo(double t);
    /// Releases the object now (GraspScene::releaseObject()) and restarts the stepper.
    void releaseObject();

    const SimTK::State& getState() const { return stepper_.getState(); }
    /// When the next IK update is due (s).
    double getNextIkTime() const { return nextIk_; }
    /// Steps taken since construction (s).
    long getNumSteps() const { return steps_; }

private:
    void takeStep(double t);

    const GraspScene& scene_;
    SimTK::SemiExplicitEulerTimeStepper stepper_;
    double stepSize_;
    double nextIk_ = 0;
    long steps_ = 0;
};

}  // namespace graspsim::simulation
