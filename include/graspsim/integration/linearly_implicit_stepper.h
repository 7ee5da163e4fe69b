#pragma once
/// @file
/// A linearly implicit stepper for stiff contact: analytic force Jacobians, one LU of a
/// mobility-sized matrix per step, no Newton iteration. Two methods on the same matrix:
///
/// Order 1, linearly implicit ("semi-implicit") Euler, as MuJoCo's implicit integrator. Per step
/// of size h from (t, q, u, z), realized through Stage::Acceleration:
///
///     f  = M udot                                   (every applied and Coriolis force)
///     D, K from the ForceJacobianContributor list  (force_jacobian.h)
///     (M - h D - h^2 K) du = h (f + h K u)          (forces at the step's end, linearized)
///     u' = u + du,  q' = q + h N(q) u',  z' = z + h zdot
///
/// Order 2 (the default), the Rosenbrock method ROS2 (Verwer et al. 1999): two stages with
/// M - gamma h D - (gamma h)^2 K, gamma = 1 + 1/sqrt(2), two dynamics evaluations; L-stable, and
/// second order for any approximate Jacobian (a W-method), so D and K may leave terms out, M is
/// kept for 10 ms, and with error control the whole matrix and its LU are kept across steps until
/// the contributors' active set changes (see findStepMatrix in the class). Optionally
/// error-controlled (LinearlyImplicitOptions::accuracy): steps up to h chosen from the difference
/// to the embedded first-order solution.
///
/// A locked mobilizer's rows are du = 0. After each step q and u are projected onto the
/// constraints with System::project (without constraints, quaternions are only normalized).
/// With D and K of the stiff forces (contact, joint impedance) the step is stable where explicit
/// methods need microsecond steps; forces left out of D and K are treated explicitly.
/// Measurements and why: docs/performance.md.
///
/// Events: at fixed steps, scheduled events, reports and stepTo() times land exactly on their
/// times (the interval up to each is cut into equal steps no longer than h). With error control
/// (LinearlyImplicitOptions::interpolate) the steps go on past stepTo() times and reports, and the
/// state there is interpolated (cubic Hermite from both ends of the step), as CPodes does; they
/// land on scheduled events whose handlers changed the state last time (the IK's new targets),
/// while events that changed nothing (an engaged grasp switch's check) are handled on the
/// interpolated state too, and on LinearlyImplicitOptions::landingTimes. Event triggers (witness
/// functions) are checked at the end of every step and a sign change in a direction the event
/// asks for is handled there, at the step's end (localized to within one step, not to a root
/// tolerance); a step that passes an output time and triggers is taken again, ending there. A
/// handler's change needs no restart (a one-step method keeps no history): the next step starts
/// from the changed state. Auto-update discrete variables are updated after every step.
///
/// Switches (error control): a step at whose end a term of the contributors' active set that was
/// active at its start is gone (a contact starts sliding or lets go) is taken again, bisecting
/// toward the switch down to Simbody's event localization window (accuracy x the System's time
/// scale x 0.1): the matrix kept that term's stiffness past the switch, where the error estimate
/// cannot see it. Landing times: the step that ends on one sees the inputs from the left there
/// (the jump belongs to the next step), and the steps after it start again from that window.
///
/// Fixed steps (ROS2 without error control) are still checked: each step's embedded error
/// estimate is computed against the state's own scale (the norm above with accuracy 1), and a
/// step where it exceeds kUntrustedStepEstimate throws FixedStepTooLongError instead of going on
/// from a state neither of the step's two solutions vouches for. This catches a step that is
/// unstable (the estimate grows with the state) or straddles something it cannot resolve; it does
/// not bound the run's global error (a run can drift to a wrong answer with every step's estimate
/// far below the state's scale: docs/performance.md, "Fixed steps that cannot be trusted").
/// Linearly implicit Euler (order 1) has no embedded solution and is not checked.

#include "graspsim/integration/force_jacobian.h"
#include "graspsim/integration/stepper.h"

#include "graspsim/simbody.h"

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace graspsim::integration {

/// Settings of the linearly implicit stepper.
struct LinearlyImplicitOptions {
    double stepSize = 1e-3;             ///< h (s), the longest step; finite and > 0
    double constraintTolerance = 1e-6;  ///< System::project accuracy after each step
    /// 1: linearly implicit Euler (one dynamics evaluation per step); 2: the two-stage Rosenbrock
    /// method ROS2 with the same matrix (two evaluations, one factorization per step).
    int order = 2;
    /// With order 2: > 0 turns on step-size control, steps no longer than stepSize chosen so that
    /// the error estimate (the difference from the embedded first-order solution, weighted RMS,
    /// Simbody's convention: accuracy (1 + |y|) per entry) stays below it; 0: fixed steps.
    double accuracy = 0;
    /// With error control: reports and scheduled events that fall inside a step are served on the
    /// state interpolated there (dense output) instead of ending a step on each; false: steps end
    /// on them, as at fixed steps.
    bool interpolate = true;
    /// Times (s, finite) the steps end on exactly when they interpolate: where the inputs jump (a
    /// perturbation force switched on or off), so that no step straddles a discontinuity. Without
    /// interpolation the steps end on every stepTo() time, which the callers put at these times.
    /// A step ending on one evaluates its second stage just before it; with error control the
    /// steps after one start again from the switch localization window (see the file comment).
    std::vector<double> landingTimes;
};

/// The linearly implicit stepper (see the file comment). The System and the
/// contributors must outlive it.
class StepMatrix;  // src/integration/step_matrix.h
class NMatrix;     // src/integration/n_matrix.h
class DenseOutput;  // src/integration/dense_output.h
class StepSizeControl;  // src/integration/step_size_control.h
class SwitchLocalization;  // src/integration/switch_localization.h

class LinearlyImplicitStepper : public Stepper {
public:
    /// @throws graspsim::InputError naming the option when the step size or the tolerance is not
    ///         finite and > 0. stepTo() throws FixedStepTooLongError (an InputError) at fixed
    ///         ROS2 steps when a step cannot be trusted (see the file comment).
    LinearlyImplicitStepper(const SimTK::MultibodySystem& system, std::vector<const ForceJacobianContributor*> contributors,
                            const LinearlyImplicitOptions& options = {});
    ~LinearlyImplicitStepper() override;

    void initialize(const SimTK::State& initial) override;
    void stepTo(double time) override;
    /// The state at the last stepTo() time: the integrator's own, or interpolated inside its last step.
    const SimTK::State& getState() const override;
    long getNumStepsTaken() const override { return steps_ - stepsAtInitialize_; }
    IntegrationStatistics getStatistics() const override;
    /// The largest error estimate a fixed ROS2 step may have, against the state's own scale (each
    /// entry over 1 + |y|, weighted RMS): beyond it the step's second- and first-order solutions
    /// differ by more than the state itself. Not tuned: the scale is the state's. Measured on the
    /// five shipped scenes (docs/performance.md): runs at 1 ms stay below 0.12 (0.37 in a capacity
    /// ramp as the ball drops); the runs that blow up cross it (first at 1.02 to 664).
    static constexpr double kUntrustedStepEstimate = 1.0;

    /// "linearly-implicit-euler" (order 1) or "rosenbrock-ros2" (order 2).
    std::string getMethodName() const override { return options_.order == 1 ? "linearly-implicit-euler" : "rosenbrock-ros2"; }
    const LinearlyImplicitOptions& getOptions() const { return options_; }

private:
    bool handleDueScheduledEvents();
    void advance(double tStop);
    void advanceControlled(double tStop);
    void stepToInterpolating(double time);
    bool takeControlledStep(double tStop);
    void restoreStepStart(double t, const SimTK::Vector& q, const SimTK::Vector& u, const SimTK::Vector& z);
    void showAt(double t);
    bool handleInterpolatedEvents(const SimTK::HandleEventsResults& results);
    double findNextLanding(double t) const;
    double findStop(double target, double nextEvent) const;
    bool interpolates() const { return options_.accuracy > 0 && options_.interpolate; }
    bool takeStep(double h, double& error);
    void project(SimTK::State& state);
    void takeEulerStep(double h);
    double takeRosenbrockStep(double h);
    const StepMatrix& findStepMatrix(double g);
    void solve(const StepMatrix& A, std::vector<double>& b) const;  // A^-1 b in place, timed
    double calcErrorNorm(const StepMatrix& A, double h, const std::vector<double>& a1, const std::vector<double>& a2,
                         const std::vector<double>& b1, const std::vector<double>& b2, const std::vector<double>& u0,
                         double accuracy) const;
    void setState(double t, const SimTK::Vector& q, const SimTK::Vector& u, const SimTK::Vector& z);
    void handleResults(const SimTK::HandleEventsResults& results);

    const SimTK::MultibodySystem& system_;
    std::vector<const ForceJacobianContributor*> contributors_;
    LinearlyImplicitOptions options_;
    SimTK::State state_;
    SimTK::Vector triggers_;                         // the event triggers at the state's time
    SimTK::Array_<SimTK::EventTriggerInfo> triggerInfo_;
    long rejectedSteps_ = 0;
    // M of the step matrix, kept for kMassMatrixAge: ROS2 is a W-method (second order with any
    // W), and the arm's mass matrix changes slowly; calcM was a fifth of a step.
    static constexpr double kMassMatrixAge = 0.01;  // s
    std::vector<double> massMatrix_;
    double massMatrixTime_ = -SimTK::Infinity;
    // W = M - g D - g^2 K with its LU kept across error-controlled ROS2 steps (a W-method stays
    // second order with a stale W; the error estimate watches) until the active set of the
    // contributors (contacts pushing, stops engaged) changes, a step is rejected, an event changes
    // the Instance stage, the step's g moves beyond kMatrixStepRatio of the one it was built
    // with, or it is kMatrixAge old. Measurements: docs/performance.md.
    static constexpr double kMatrixAge = 0.01;       // s
    static constexpr double kMatrixStepRatio = 1.1;  // g / g_built within (1/1.1, 1.1)
    std::unique_ptr<StepMatrix> matrix_;
    std::unique_ptr<NMatrix> n0_;  // N(q0) of the step under way
    // Dense output (interpolates()): the state interpolated in the last step, whether getState()
    // is that one, and the latest time a triggered event may be handled at (an output time inside
    // the step must see the state before that event: such a step is taken again, ending there).
    std::unique_ptr<DenseOutput> dense_;
    std::unique_ptr<StepSizeControl> stepSizes_;  // error control only
    // Error control only: where a step lost an active term, bisected down to a window.
    std::unique_ptr<SwitchLocalization> switches_;
    // Active sets: each term its contributor's place in contributors_ (high 32 bits) and the
    // contributor's own identifier (low 32 bits), so that two contributors' equal identifiers (a
    // joint stop's mobilized body index and a contact pair's 2 i + 1) stay two terms.
    void findActiveSet(std::vector<std::int64_t>& set) const;
    mutable std::vector<int> contributorTerms_;  // scratch for findActiveSet
    // A step that lost terms: their margins at its end (ForceJacobianContributor::findTermMargin),
    // from which, with those at its start, the switch's time is estimated.
    void findLostMargins(const std::vector<std::int64_t>& lost);
    double findTermMargin(std::int64_t term) const;
    double estimateSwitchTime(double t, double h) const;
    std::vector<std::pair<std::int64_t, double>> lostMargins_;
    std::vector<std::int64_t> endSet_;  // the active set at the last step's end
    bool switchCrossed_ = false;
    bool outputInterpolated_ = false;
    double eventHorizon_ = SimTK::Infinity;
    bool redo_ = false;
    // Whether the steps end on the next scheduled event. An event whose handlers change the state
    // (the fingertip IK's new PD targets, every 10 ms in full contact) is one the steps land on, as
    // at fixed steps: handled at an interpolated instant, its change would reach the dynamics only
    // from the next step on. One whose handlers changed nothing last time (the grasp switch's
    // check while engaged, the IK paused) is expected to change nothing again and is served on an
    // interpolated state; if it does change something, handleInterpolatedEvents() carries a
    // Report-stage change on or restarts from the interpolated state, and the next one lands.
    bool landOnEvents_ = true;
    double matrixTime_ = -SimTK::Infinity;
    std::vector<std::int64_t> matrixActiveSet_, activeSet_;
    bool matrixStale_ = true;
    long matrixBuilds_ = 0;
    mutable double linearSolveSeconds_ = 0;  // building, factoring, solving (s)
    double lastEventTime_ = -SimTK::Infinity, lastReportTime_ = -SimTK::Infinity;
    long steps_ = 0, stepsAtInitialize_ = 0, evaluations_ = 0, projections_ = 0;
    long scheduledEvents_ = 0, triggeredEvents_ = 0;
    bool initialized_ = false, terminated_ = false;
};

}  // namespace graspsim::integration
