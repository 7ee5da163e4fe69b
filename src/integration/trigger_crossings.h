#pragma once
// Which event triggers (witness functions) changed sign over a step, in a direction their events
// ask for: the linearly implicit stepper checks them at the end of every step.

#include "graspsim/simbody.h"

namespace graspsim::integration {

// The events whose triggers went from `before` to `now` across zero in a direction `info` asks for
// (none when the number of triggers changed: an Instance-stage change, after which `now` is the
// new reference).
SimTK::Array_<SimTK::EventId> findTriggeredEvents(const SimTK::Array_<SimTK::EventTriggerInfo>& info,
                                                  const SimTK::Vector& before, const SimTK::Vector& now);

}  // namespace graspsim::integration
