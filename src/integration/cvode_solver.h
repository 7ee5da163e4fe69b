#pragma once
// Private to the integration layer: the SUNDIALS objects behind CvodeIntegrator and the C
// callbacks that evaluate a Simbody System for CVODE. Kept out of the public header so that
// users of cvode_integrator.h do not see SUNDIALS' C headers.

#include "graspsim/integration/cvode_integrator.h"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>

#include <simbody/Simbody.h>

#include <string>

namespace graspsim::integration {

// What the C callbacks need: the System and a scratch State that carries the discrete
// variables of the state CVODE was started from. Exceptions must not cross the C code, so a
// callback catches them, keeps the message here and returns an error code.
struct CvodeCallbackContext {
    const SimTK::System* system = nullptr;
    SimTK::State work;
    double constraintTolerance = 0;
    SimTK::Stage triggerStage = SimTK::Stage::Empty;  // realize this far to evaluate the triggers
    std::string lastCallbackError;
    std::string lastCvodeMessage;
};

class CvodeSolver {
public:
    CvodeSolver(const SimTK::System& system, const CvodeOptions& options, double constraintTolerance);
    ~CvodeSolver();
    CvodeSolver(const CvodeSolver&) = delete;
    CvodeSolver& operator=(const CvodeSolver&) = delete;

    // (Re)starts CVODE at `s` (realized through Instance): tolerances, triggers and sizes are
    // read from it anew, and the method restarts at order 1.
    void start(const SimTK::State& s);
    // Hands the callbacks `s`'s discrete variables without restarting CVODE: for a Report-stage
    // change, which nothing CVODE has computed depends on (a ramp of the PD targets planned ahead).
    void carryDiscreteVariables(const SimTK::State& s) { context_.work = s; }
    // Integrates to tStop, or to the first trigger zero crossing before it. Writes the time and
    // y reached into `s`; returns true when it stopped at a crossing.
    bool advance(double tStop, SimTK::State& s);
    // The events whose triggers crossed zero in a direction they ask for, at the last crossing.
    SimTK::Array_<SimTK::EventId> findTriggeredEvents() const;
    // Counts since construction (CVODE's own restart at each start()).
    IntegrationStatistics getStatistics() const;

private:
    void create(int ny);
    void destroy();
    void setTolerances(const SimTK::State& s);
    void setTriggers(const SimTK::State& s);
    void foldCurrentCounts();
    void addCurrentCountsTo(IntegrationStatistics& statistics) const;
    [[noreturn]] void fail(const std::string& call, int flag, double t) const;
    void check(const std::string& call, int flag) const;

    CvodeOptions options_;
    CvodeCallbackContext context_;
    SUNContext sunContext_ = nullptr;
    void* cvode_ = nullptr;
    N_Vector y_ = nullptr;
    N_Vector absoluteTolerance_ = nullptr;
    SUNMatrix jacobian_ = nullptr;
    SUNLinearSolver linearSolver_ = nullptr;
    int ny_ = -1;
    SimTK::Array_<SimTK::EventTriggerInfo> triggerInfo_;
    IntegrationStatistics totals_;  // of the runs before the current one
};

}  // namespace graspsim::integration
