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

}  // namespace graspsim::integration
