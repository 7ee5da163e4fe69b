#include "trigger_crossings.h"

namespace graspsim::integration {

namespace {

// Whether a trigger going from `before` to `after` crosses zero in a direction `info` asks for.
bool isCrossing(const SimTK::EventTriggerInfo& info, double before, double after) {
    if (before == 0 || (before > 0) == (after > 0)) return false;
    if (after == 0 && before > 0) return info.shouldTriggerOnFallingSignTransition();
    return after > before ? info.shouldTriggerOnRisingSignTransition() : info.shouldTriggerOnFallingSignTransition();
}

}  // namespace

SimTK::Array_<SimTK::EventId> findTriggeredEvents(const SimTK::Array_<SimTK::EventTriggerInfo>& info,
                                                  const SimTK::Vector& before, const SimTK::Vector& now) {
    SimTK::Array_<SimTK::EventId> events;
    if (now.size() != before.size()) return events;
    for (int i = 0; i < now.size(); ++i) {
        if (isCrossing(info[i], before[i], now[i])) events.push_back(info[i].getEventId());
    }
    return events;
}

}  // namespace graspsim::integration
