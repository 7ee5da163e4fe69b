#pragma once
/// @file
/// A reference integrator: SUNDIALS CVODE (variable-order BDF with Newton iteration, dense
/// finite-difference Jacobian) driving any Simbody System through its state vector, so that
/// Simbody's results can be checked against an independent, widely used ODE code.
///
/// The ODE is y = [q, u, z] (State::getY), ẏ from System::realize(Acceleration)
/// (State::getYDot). Around it:
///  - projection: after every successful step CVODE calls its projection hook, which applies
///    prescribed motion (System::prescribeQ/U) and projects q and u onto the constraint
///    manifold (System::projectQ/projectU, LocalOnly) to the constraint tolerance, projecting
///    CVODE's local error estimate with them;
///  - triggered events: the System's event triggers (witness functions) are CVODE's root
///    functions, with the directions Simbody asks for (EventTriggerInfo); at a root the
///    triggered events are handled (System::handleEvents, cause Triggered);
///  - scheduled events and reports (System::calcTimeOfNextScheduledEvent/Report) are CVODE
///    stop times, so they land exactly on their times;
///  - a handler's or the caller's change to the state restarts CVODE (CVodeReInit) from it.
///
/// Tolerances: CVODE's error weight for y_i is 1 / (rtol |y_i| + atol_i). rtol is
/// CvodeOptions::relativeTolerance; atol_i is absoluteTolerance divided by the State's unit
/// weight of that variable (State::getUWeights for u, getZWeights for z, 1 for q, whose
/// weights Simbody defines only through N(q)). With Simbody's default weights (all 1) that is
/// one scalar atol. The default atol = rtol follows Simbody's own accuracy convention (a
/// relative error, turning absolute below unit magnitude).
///
/// Limits: auto-update discrete variables are updated at stepTo() and event boundaries, not
/// after every internal step; TimeAdvanced events are not generated.

#include "graspsim/integration/stepper.h"

#include "graspsim/simbody.h"

#include <memory>
#include <string>

namespace graspsim::integration {

/// CVODE settings. Zero means "derived", as documented per field.
struct CvodeOptions {
    double relativeTolerance = 1e-3;  ///< rtol (dimensionless)
    double absoluteTolerance = 0;     ///< atol in unit-weighted state units; 0 = relativeTolerance
    double constraintTolerance = 0;   ///< Simbody projection accuracy (RMS of weighted constraint errors); 0 = relativeTolerance
    bool projection = true;           ///< project onto the constraint manifold after every step
    int maxOrder = 5;                 ///< highest BDF order (1..5)
    double maxStepSize = 0;           ///< largest step (s); 0 = unlimited
    long maxStepsPerInterval = 1000000;  ///< internal steps allowed between two stops (output, event)
};

class CvodeSolver;  // the SUNDIALS objects (src/integration/cvode_solver.h)

/// Steps a Simbody System with CVODE; the shape of SimTK::TimeStepper.
/// The System must outlive the integrator.
class CvodeIntegrator : public Stepper {
public:
    explicit CvodeIntegrator(const SimTK::System& system, const CvodeOptions& options = {});
    ~CvodeIntegrator() override;
    CvodeIntegrator(const CvodeIntegrator&) = delete;
    CvodeIntegrator& operator=(const CvodeIntegrator&) = delete;

    void initialize(const SimTK::State& initial) override;
    void stepTo(double time) override;
    const SimTK::State& getState() const override { return state_; }
    /// The state to change between stepTo() calls (e.g. an Instance-stage change such as a
    /// mobilizer lock); the next stepTo() notices the change and restarts CVODE from it.
    SimTK::State& updState() { return state_; }
    long getNumStepsTaken() const override;
    IntegrationStatistics getStatistics() const override;
    std::string getMethodName() const override { return "cvode-bdf"; }
    /// True once an event handler asked to end the simulation; stepTo() then does nothing.
    bool isTerminated() const { return terminated_; }
    const CvodeOptions& getOptions() const { return options_; }
    /// The constraint tolerance in use (CvodeOptions::constraintTolerance or its default).
    double getConstraintTolerance() const;

private:
    void restart();
    void advance(double tStop);
    bool handleDueScheduledEvents();
    void handleTriggeredEvents();
    bool applyHandlerResults(const SimTK::HandleEventsResults& results);
    void saveStageVersions();

    const SimTK::System& system_;
    CvodeOptions options_;
    std::unique_ptr<CvodeSolver> solver_;
    SimTK::State state_;
    SimTK::Array_<SimTK::StageVersion> stageVersions_;  // of state_ when CVODE last saw it
    double lastEventTime_ = -SimTK::Infinity;
    double lastReportTime_ = -SimTK::Infinity;
    bool terminated_ = false;
    bool initialized_ = false;
    long stepsAtInitialize_ = 0;
    IntegrationStatistics events_;  // the event and restart counts kept here
};

}  // namespace graspsim::integration
