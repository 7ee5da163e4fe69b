#pragma once
/// @file
/// The one place where the model description's plain arrays become Simbody types.

#include <string>

#include "graspsim/model/model_description.h"
#include "graspsim/simbody.h"

namespace graspsim::system {

/// v as a SimTK::Vec3 (same components, same units and frame).
SimTK::Vec3 toSimTKVec3(const model::Vec3& v);

/// X_AB as a SimTK::Transform (same rotation and translation, m).
/// @throws graspsim::InputError, starting with `what`, if X_AB.R is not a proper rotation
///         (‖R Rᵀ − I‖_F ≥ 1e-9 or det R < 0).
SimTK::Transform toSimTKTransform(const model::Transform& X_AB, const std::string& what);

}  // namespace graspsim::system
