#pragma once
/// @file
/// Turning a right-side limb into a left-side one.

#include "graspsim/model/model_description.h"

#include <cstddef>

namespace graspsim::model {

/// Mirrors across the sagittal plane (z -> -z) the bodies, joints and end-effectors of `model`
/// from the given indices on. Points and translations flip z; rotations R become M R M with
/// M = diag(1, 1, -1); joint axes, being rotation axes, become (-x, -y, z); inertia products
/// with z flip sign. Equal joint angles then give mirror-image poses.
void mirrorSagittally(ModelDescription& model, std::size_t firstBody, std::size_t firstJoint,
                      std::size_t firstEndEffector);

}  // namespace graspsim::model
