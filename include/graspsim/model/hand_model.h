#pragma once
/// @file
/// The anthropometric hand: palm (two boxes), five digits of capsule phalanges, fingertip
/// end-effectors, and the wrist joints that attach it to the forearm.
///
/// Hand length HL (wrist crease to the tip of the middle finger) comes from stature; phalanx
/// lengths are Buchholz et al. (1992) coefficients x HL. The MCP joint of digit k sits
/// (1 - P3 - M3 - D3 - MC3 + MCk) HL distal to the wrist, so the extended middle finger ends
/// exactly HL from the wrist. The de Leva hand mass is shared over palm and phalanges in
/// proportion to their volumes (one density).
///
/// Hand frame (palm body, at the wrist joint centre, right hand, anatomical position): x palmar
/// (anterior), y proximal along the third metacarpal, z radial (toward the thumb). Fingers extend
/// along -y; flexion is positive about +z for the fingers. Degrees of freedom: wrist 2, index to
/// little MCP 2 + PIP 1 + DIP 1 each, thumb CMC 2 + MCP 1 + IP 1: 22 in all.

#include "graspsim/anthropometry/subject.h"
#include "graspsim/model/model_description.h"

#include <string>

namespace graspsim::model {

/// What addHand needs besides the model it adds to.
struct HandSpec {
    anthropometry::Subject subject;  ///< sizes and the de Leva hand mass
    std::string prefix;              ///< prepended to every body, joint and end-effector name (e.g. "l_")
    double fingerStiffness = 0.25;   ///< N m/rad, every finger and thumb joint
    double fingerDamping = 0.05;     ///< N m s/rad
    double wristStiffness = 0.0;     ///< N m/rad
    double wristDamping = 0.5;       ///< N m s/rad
};

/// Hand length, wrist crease to the tip of the middle finger (m).
double calcHandLength(const anthropometry::Subject& subject);

/// Adds the hand to `model`: the palm hangs from `parent` through the wrist flexion and
/// deviation joints placed at X_PW (the wrist joint centre in the parent frame).
/// End-effectors "<prefix><digit>_tip" lie on the pad of each distal phalanx.
void addHand(ModelDescription& model, const std::string& parent, const Transform& X_PW, const HandSpec& spec);

}  // namespace graspsim::model
