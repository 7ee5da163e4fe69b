#include "graspsim/model/body_model.h"

#include "graspsim/model/arm_model.h"
#include "graspsim/model/humanoid_model.h"
#include "graspsim/model/thesis_preset.h"

#include "graspsim/error.h"

namespace graspsim::model {

ModelDescription buildBodyModel(const BuildOptions& options) {
    validateBuildOptions(options);
    ModelDescription model = options.body == BodyKind::Arm ? buildArmModel(options) : buildHumanoidModel(options);
    if (options.preset == Preset::Thesis) applyThesisPreset(model);
    for (const SegmentPoint& point : options.segmentPoints) {
        if (model.findEndEffector(point.name)) {
            throw InputError("segment point '" + point.name + "': the model has an end-effector of that name already");
        }
        model.endEffectors.push_back({point.name, point.body, {point.p_B[0], point.p_B[1], point.p_B[2]}});
    }
    model.validate("model builder");  // also an added point's unknown body or repeated name
    return model;
}

}  // namespace graspsim::model
