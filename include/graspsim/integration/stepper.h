#pragma once
/// @file
/// The time-stepping interface a simulation drives: Simbody's TimeStepper shape (initialize,
/// stepTo, getState), so that Simbody's own integrators and the SUNDIALS CVODE reference
/// (cvode_integrator.h) can be swapped without touching the simulation loop.

#include "graspsim/simbody.h"

#include <string>

namespace graspsim::integration {

/// What an integrator did, summed from construction over every initialize() (unlike
/// getNumStepsTaken(), which restarts at each initialize(), as Simbody's does). A count the
/// integrator does not report is -1.
struct IntegrationStatistics {
    long steps = 0;                  ///< successful steps
    long rhsEvaluations = 0;         ///< state-derivative evaluations (realize to Acceleration), Jacobian ones included
    long jacobianEvaluations = -1;   ///< Newton iteration matrix (Jacobian) evaluations
    long linearSolverSetups = -1;    ///< factorizations of the Newton iteration matrix
    long errorTestFailures = 0;      ///< steps rejected by the local error test
    long convergenceFailures = 0;    ///< steps rejected because the Newton iteration failed
    long projections = 0;            ///< projections onto the constraint manifold
    long rootEvaluations = -1;       ///< event-trigger (witness) evaluations
    long triggeredEvents = -1;       ///< event-trigger zero crossings handled
    long scheduledEvents = -1;       ///< scheduled event times handled
    long restarts = -1;              ///< integrator restarts (after a state change by an event or the caller)
    long newtonIterations = -1;      ///< nonlinear (Newton) iterations; 0 for a linearly implicit method
    /// Wall time (s) spent building, factoring and solving with the step's linear system, where the
    /// stepper measures it itself (the linearly implicit stepper); -1 otherwise.
    double linearSolveSeconds = -1;
};

/// Advances a SimTK::System's State in time, handling the System's events on the way.
class Stepper {
public:
    virtual ~Stepper() = default;
    /// Starts (or restarts) from `initial` at its time: projects it onto the constraints and
    /// handles Initialization events.
    virtual void initialize(const SimTK::State& initial) = 0;
    /// Advances to exactly `time` (s), handling scheduled and triggered events before it.
    /// @throws graspsim::NumericalError when the integrator cannot proceed (time and reason in the message).
    virtual void stepTo(double time) = 0;
    /// The state reached (realized through Acceleration after a step).
    virtual const SimTK::State& getState() const = 0;
    /// Successful steps since the last initialize().
    virtual long getNumStepsTaken() const = 0;
    /// Counts since construction.
    virtual IntegrationStatistics getStatistics() const = 0;
    /// A short name of the method, e.g. "cvode-bdf".
    virtual std::string getMethodName() const = 0;
};

}  // namespace graspsim::integration
