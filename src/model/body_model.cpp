#include "graspsim/model/body_model.h"

#include "graspsim/model/arm_model.h"
#include "graspsim/model/humanoid_model.h"
#include "graspsim/model/thesis_preset.h"

namespace graspsim::model {

ModelDescription buildBodyModel(const BuildOptions& options) {
    validateBuildOptions(options);
    ModelDescription model = options.body == BodyKind::Arm ? buildArmModel(options) : buildHumanoidModel(options);
    if (options.preset == Preset::Thesis) applyThesisPreset(model);
    model.validate("model builder");
    return model;
}

}  // namespace graspsim::model
