#include "graspsim/simulation/object_hold.h"

namespace graspsim::simulation {

bool ObjectHold::isHeld(const SimTK::State& state) const {
    return isByGroundWeld() ? !groundWeld_.isDisabled(state) : object_.isLocked(state);
}

void ObjectHold::release(SimTK::State& state) const {
    if (isByGroundWeld()) {
        groundWeld_.disable(state);
    } else {
        object_.unlock(state);
    }
}

}  // namespace graspsim::simulation
