#pragma once
/// @file
/// The anthropometric arm: upper arm and forearm from de Leva (1996), with the hand of
/// hand_model.h, hanging from a shoulder.
///
/// Joints (right arm, all zero in the rest pose: arm hanging, forearm neutral with the thumb
/// forward): shoulder flexion (+z), abduction (-x), internal rotation (+y) [3]; elbow flexion (+z) [1];
/// forearm pronation (+y, 0 = neutral) [1]; then the hand's wrist 2 + fingers 16 + thumb 4.
/// The stand-alone arm has 27 DOF. The three shoulder DOF are an Euler sequence and lock
/// (gimbal lock) at 90 degrees of abduction; grasping poses stay well away from it.

#include "graspsim/model/build_options.h"
#include "graspsim/model/model_description.h"

#include <string>

namespace graspsim::model {

/// Passive joint parameters and naming of one arm.
struct ArmSpec {
    anthropometry::Subject subject;
    std::string prefix;             ///< prepended to every name (e.g. "r_")
    double fingerStiffness = 0.25;  ///< N m/rad
    double fingerDamping = 0.05;    ///< N m s/rad
    double armStiffness = 0.0;      ///< N m/rad: shoulder, elbow, forearm, wrist
    double armDamping = 0.5;        ///< N m s/rad: shoulder, elbow, forearm, wrist
};

/// Adds an arm whose shoulder joint centre is at X_PS in `parent`.
void addArm(ModelDescription& model, const std::string& parent, const Transform& X_PS, const ArmSpec& spec);

/// The stand-alone right arm: a massless "shoulder_anchor" root at the ground origin, the
/// shoulder joint centre there.
ModelDescription buildArmModel(const BuildOptions& options);

}  // namespace graspsim::model
