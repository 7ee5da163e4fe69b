#include "scheduled_times.h"

namespace graspsim::integration {

ScheduledTimes findScheduledTimes(const SimTK::System& system, const SimTK::State& state, bool eventNow, bool reportNow) {
    ScheduledTimes next;
    system.realize(state, SimTK::Stage::Time);
    system.calcTimeOfNextScheduledEvent(state, next.event, next.eventIds, eventNow);
    system.calcTimeOfNextScheduledReport(state, next.report, next.reportIds, reportNow);
    return next;
}

DueScheduled handleDueScheduled(const SimTK::System& system, SimTK::State& state, double constraintTolerance,
                                double& lastEventTime, double& lastReportTime, SimTK::HandleEventsResults& results) {
    const double t = state.getTime();
    const ScheduledTimes due = findScheduledTimes(system, state, lastEventTime != t, lastReportTime != t);
    if (due.report <= t) {
        system.realize(state, SimTK::Stage::Acceleration);
        system.reportEvents(state, SimTK::Event::Cause::Scheduled, due.reportIds);
        lastReportTime = t;
        return DueScheduled::Reported;
    }
    if (due.event > t) return DueScheduled::Nothing;
    system.handleEvents(state, SimTK::Event::Cause::Scheduled, due.eventIds,
                        SimTK::HandleEventsOptions(constraintTolerance), results);
    lastEventTime = t;
    return DueScheduled::Handled;
}

}  // namespace graspsim::integration
