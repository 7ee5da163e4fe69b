#include "graspsim/simulation/constraint_sample.h"

#include "graspsim/simulation/approximation_context.h"

namespace graspsim::simulation {

std::optional<ConstraintSample> findConstraintSample(const ApproximationContext& context, const SimTK::State& state) {
    const grasp::GraspAttachment& attachment = context.attachment;
    if (!attachment.isEngaged(state)) return std::nullopt;
    context.model.getSystem().realize(state, attachment.getReactionStage());
    const std::optional<grasp::SingleConstraintState> c = attachment.findSingleConstraintState(state);
    if (!c) return std::nullopt;
    ConstraintSample sample;
    sample.time = state.getTime();
    sample.X_GM = context.object.getBodyTransform(state) * c->X_OM;
    sample.limits = c->limits;
    sample.lowerLimits = c->lowerLimits;
    sample.reaction = c->reaction;
    sample.wrench_G = c->wrench_G;
    return sample;
}

}  // namespace graspsim::simulation
