#include "graspsim/simulation/fingertip_goals.h"

#include <algorithm>

namespace graspsim::simulation {

void FingertipGoals::add(const std::string& endEffector, const SimTK::Vec3& p_OT) {
    endEffectors_.push_back(endEffector);
    surfacePoints_.push_back(p_OT);
}

double FingertipGoals::findDistance(const SimTK::State& state, std::size_t k) const {
    const SimTK::Vec3 p_GE = model_->findEndEffectorLocationInGround(state, endEffectors_[k]);
    return (p_GE - object_->getBodyTransform(state) * surfacePoints_[k]).norm();
}

double FingertipGoals::findMaxDistance(const SimTK::State& state) const {
    model_->getSystem().realize(state, SimTK::Stage::Position);
    double worst = 0;
    for (std::size_t k = 0; k < endEffectors_.size(); ++k) worst = std::max(worst, findDistance(state, k));
    return worst;
}

}  // namespace graspsim::simulation
