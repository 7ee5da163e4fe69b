#include "dense_output.h"

namespace graspsim::integration {

void DenseOutput::initialize(const SimTK::State& state) {
    reportVariables_ = findReportVariables(state);
    hasAutoUpdate_ = hasAutoUpdateVariables(state);
    inSync_ = false;
}

// A State copy costs about two evaluations (Simbody copies every cache entry): it is made only
// when the integrator's State changed otherwise than in time, q, u and z since the last one.
SimTK::State& DenseOutput::interpolate(const SimTK::State& end, double t) {
    if (!inSync_) state_ = end;
    inSync_ = !hasAutoUpdate_;
    state_.updTime() = t;
    start_.interpolate(end, t, state_.updY());
    return state_;
}

bool DenseOutput::handOn(const SimTK::HandleEventsResults& results, SimTK::State& integrator) const {
    const SimTK::Stage lowest = results.getLowestModifiedStage();
    const bool failed = results.getExitStatus() != SimTK::HandleEventsResults::Succeeded;
    if (failed || lowest < SimTK::Stage::Report) return false;
    if (lowest == SimTK::Stage::Report) copyReportVariables(reportVariables_, state_, integrator);
    return true;
}

}  // namespace graspsim::integration
