#pragma once
/// @file
/// Writing a ModelDescription as URDF text that reads back exactly (see urdf_import.h).
///
/// - Numbers are written as the shortest decimal text that reads back bit for bit (urdfdom's own
///   exporter keeps only 6 significant digits), in the "C" locale.
/// - Each body is a `<link>`; its `<inertial>` has origin xyz = p_BCm, rpy = 0 and the central
///   inertia as given in B (omitted for a virtual body with zero com and inertia). Each geometry is
///   a `<collision>` and an identical `<visual>` (for viewers); a capsule, which URDF lacks, is the
///   cylinder and two end spheres named "<name>__capsule_cylinder", "<name>__capsule_cap_pos",
///   "<name>__capsule_cap_neg", whose union is exactly the capsule.
/// - Each joint is a `<joint>`: origin = X_PJ as xyz and rpy (R = Rz(yaw) Ry(pitch) Rx(roll),
///   extracted so that pitch = +-pi/2 stays exact); axis; `<limit lower upper effort="0"
///   velocity="0">` for revolute and prismatic joints (URDF requires effort and velocity;
///   graspsim has no actuator limits and ignores them); `<dynamics damping>` when non-zero.
/// - A non-identity X_GR is written as a massless link "world" and a fixed joint
///   "world_to_<root>" whose origin is X_GR, the ROS convention.
/// - Body::segment, Joint::stiffness and Joint::restAngle, and the end-effectors are written as
///   `<graspsim:link>`, `<graspsim:joint>` and `<graspsim:end_effector>` elements under `<robot>`,
///   with xmlns:graspsim="https://graspsim.invalid/urdf-extensions"; other URDF readers skip them.
/// To write a file, pass the text to graspsim::writeFileAtomically (graspsim/io/atomic_file.h).

#include "graspsim/model/model_description.h"

#include <string>

namespace graspsim::model {

/// The URDF text of `model`, checked by parsing it back with urdfdom.
/// @throws graspsim::InputError if `model` fails ModelDescription::validate, has a body or joint
///   whose name clashes with the "world" link and joint (when X_GR is not identity), or a geometry
///   name ending in one of the reserved capsule suffixes.
/// @throws graspsim::Error if urdfdom rejects the generated text (a bug in graspsim).
std::string writeUrdf(const ModelDescription& model);

}  // namespace graspsim::model
