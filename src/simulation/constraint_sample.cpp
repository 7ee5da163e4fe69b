#include "graspsim/simulation/constraint_sample.h"

#include "graspsim/simulation/grasp_scene.h"

namespace graspsim::simulation {

std::optional<ConstraintSample> findConstraintSample(const GraspScene& scene, const SimTK::State& state) {
    if (!scene.getGraspSwitch() || scene.getMultiAttachment()) return std::nullopt;
    const grasp::LimitedWeld* weld = scene.getWeld();
    const grasp::LimitedBushing& bushing = scene.getBushing();
    const bool engaged = weld ? weld->isEnabled(state) : (!bushing.isEmptyHandle() && bushing.isEnabled(state));
    if (!engaged) return std::nullopt;
    scene.getSystem().realize(state, SimTK::Stage::Acceleration);
    ConstraintSample sample;
    sample.time = state.getTime();
    const SimTK::Transform& X_GO = scene.getObject().getBodyTransform(state);
    if (weld) {
        sample.X_GM = X_GO * weld->getFrameOnO(state);
        sample.limits = weld->findEffectiveLimits(state);
        sample.reaction = weld->findGeneralizedForce(state);
        sample.wrench_G = weld->findWrench(state);
    } else {
        sample.X_GM = X_GO * bushing.getFrameOnO(state);
        sample.limits = bushing.findEffectiveLimits(state);
        sample.reaction = bushing.findGeneralizedForce(state);
        sample.wrench_G = bushing.findWrench(state);
    }
    return sample;
}

}  // namespace graspsim::simulation
