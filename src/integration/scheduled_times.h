#pragma once
// The System's next scheduled event and report times seen from a state: what both steppers ask
// before each step and wherever they stop.

#include <simbody/Simbody.h>

namespace graspsim::integration {

struct ScheduledTimes {
    double event = SimTK::Infinity;   // s
    double report = SimTK::Infinity;  // s
    SimTK::Array_<SimTK::EventId> eventIds, reportIds;  // due at those times
};

// Realizes `state` to Stage::Time. `eventNow` / `reportNow`: whether a time equal to the state's
// counts (false once the ones due now have been handled).
ScheduledTimes findScheduledTimes(const SimTK::System& system, const SimTK::State& state, bool eventNow, bool reportNow);

// What handleDueScheduled() did.
enum class DueScheduled { Nothing, Reported, Handled };

// For steppers that own their state (CVODE, the linearly implicit one): one call either reports
// the scheduled reports due at the state's time (realized through Acceleration first) or, if none
// is due, runs the scheduled event handlers due then (their results in `results`), as
// SimTK::TimeStepper does; `lastReportTime` / `lastEventTime` (s) mark the time as done.
DueScheduled handleDueScheduled(const SimTK::System& system, SimTK::State& state, double constraintTolerance,
                                double& lastEventTime, double& lastReportTime, SimTK::HandleEventsResults& results);

}  // namespace graspsim::integration
