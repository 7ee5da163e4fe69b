#include "graspsim/simulation/constraint_sample.h"

#include "graspsim/simulation/grasp_scene.h"

namespace graspsim::simulation {

std::optional<ConstraintSample> findConstraintSample(const GraspScene& scene, const SimTK::State& state) {
    const grasp::GraspAttachment* attachment = scene.getAttachment();
    if (!attachment || !attachment->isEngaged(state)) return std::nullopt;
    scene.getSystem().realize(state, attachment->getReactionStage());
    const std::optional<grasp::SingleConstraintState> c = attachment->findSingleConstraintState(state);
    if (!c) return std::nullopt;
    ConstraintSample sample;
    sample.time = state.getTime();
    sample.X_GM = scene.getObject().getBodyTransform(state) * c->X_OM;
    sample.limits = c->limits;
    sample.reaction = c->reaction;
    sample.wrench_G = c->wrench_G;
    return sample;
}

}  // namespace graspsim::simulation
