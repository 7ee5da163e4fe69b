#pragma once
// Rotations as URDF writes them: roll-pitch-yaw angles about fixed axes, R = Rz(yaw) Ry(pitch) Rx(roll).

#include "graspsim/model/model_description.h"

#include <array>

namespace graspsim::model {

/// Row-major rotation matrix R_AB, as in Transform::R.
using Rotation = std::array<double, 9>;

/// Roll, pitch, yaw (rad) with R_AB = Rz(yaw) Ry(pitch) Rx(roll) for an orthonormal R_AB.
/// Pitch is in [-pi/2, pi/2]. Near pitch = +-pi/2 (gimbal lock) roll and yaw are ill-determined;
/// yaw is computed from what remains of R_AB once roll is removed, so Rz Ry Rx reproduces R_AB
/// to round-off however imprecise roll is. At gimbal lock itself roll is set to 0.
Vec3 calcRpyFromRotation(const Rotation& R_AB);

/// R_AB = Rz(yaw) Ry(pitch) Rx(roll) for rpy = (roll, pitch, yaw) in rad.
Rotation calcRotationFromRpy(const Vec3& rpy);

/// Rotation matrix of the unit quaternion (x, y, z, w) (urdfdom's urdf::Rotation layout).
Rotation calcRotationFromQuaternion(double x, double y, double z, double w);

}  // namespace graspsim::model
