#pragma once
/// @file
/// The one place where the model description's plain arrays become Simbody types, and Simbody's
/// vectors and rotations become the Eigen types of the grasp analysis (grasp/).

#include <string>

#include "graspsim/model/model_description.h"
#include "graspsim/simbody.h"

#include <Eigen/Core>

namespace graspsim::system {

/// v as a SimTK::Vec3 (same components, same units and frame).
SimTK::Vec3 toSimTKVec3(const model::Vec3& v);

/// X_AB as a SimTK::Transform (same rotation and translation, m).
/// @throws graspsim::InputError, starting with `what`, if X_AB.R is not a proper rotation
///         (‖R Rᵀ − I‖_F ≥ 1e-9 or det R < 0).
SimTK::Transform toSimTKTransform(const model::Transform& X_AB, const std::string& what);

/// v as an Eigen vector (same components, same units and frame).
Eigen::Vector3d toEigenVector(const SimTK::Vec3& v);

/// R_AB as an Eigen matrix (same entries).
Eigen::Matrix3d toEigenMatrix(const SimTK::Rotation& R_AB);

}  // namespace graspsim::system
