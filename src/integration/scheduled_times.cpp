#include "scheduled_times.h"

namespace graspsim::integration {

ScheduledTimes findScheduledTimes(const SimTK::System& system, const SimTK::State& state, bool eventNow, bool reportNow) {
    ScheduledTimes next;
    system.realize(state, SimTK::Stage::Time);
    system.calcTimeOfNextScheduledEvent(state, next.event, next.eventIds, eventNow);
    system.calcTimeOfNextScheduledReport(state, next.report, next.reportIds, reportNow);
    return next;
}

}  // namespace graspsim::integration
