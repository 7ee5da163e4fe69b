#pragma once
/// @file
/// Reading a URDF file into a ModelDescription.
///
/// The standard part is read by urdfdom; a TinyXML pass before it checks the link/joint tree
/// (so every structural mistake names its line) and one after it reads graspsim's extensions.
/// urdfdom's console output is captured: problems surface only as one graspsim::InputError
/// line naming the source, the line when known, the field, the value and what is accepted.
///
/// Mapping (frames: body B = URDF link frame, joint J = URDF joint frame = child frame at q = 0):
/// - `<link>` -> Body. `<inertial>`: origin xyz -> p_BCm; the inertia, given in the inertial
///   frame I rotated by the origin's rpy, becomes I_B = R_BI I_I R_BI^T; mass -> mass. A link
///   without `<inertial>` is a massless (virtual) body.
/// - `<collision>` -> Geometry: sphere, box (size = 2 * halfLengths), cylinder, mesh (filename
///   as given; scale is not kept). Unnamed collisions are named "collision_<i>" (i = index in the
///   link); a repeated name gets "_<k>" appended. The three collisions of graspsim's capsule
///   encoding become one Capsule. `<visual>` elements are ignored.
/// - `<joint>` revolute, continuous, prismatic, fixed -> Joint::Type; floating and planar are
///   rejected. origin -> X_PJ; axis normalized; `<limit lower upper>` -> lower, upper
///   (revolute, prismatic); `<dynamics damping>` -> damping (friction is not kept).
/// - A root link named "world" with no inertial, no geometry and exactly one child joint, of
///   type fixed, is folded away: that joint's origin becomes ModelDescription::X_GR.
/// - `<graspsim:link segment>`, `<graspsim:joint stiffness rest_angle>` and
///   `<graspsim:end_effector link xyz>` set Body::segment, Joint::stiffness, Joint::restAngle
///   and ModelDescription::endEffectors.
/// Bodies come in file order, moved only as needed for every parent to precede its children
/// (so the root is first); joints come in file order.

#include "graspsim/model/model_description.h"

#include <string>

namespace graspsim::model {

/// Reads URDF text.
/// @param xml the URDF document.
/// @param source names the text's origin (normally its file name) in error messages.
/// @throws graspsim::InputError for malformed XML (with line and column), a joint naming a
///   missing link, a link with two parents, a cycle, more than one root, a floating or planar
///   joint, a negative or non-finite mass, a massive link whose inertia is not positive definite
///   or breaks the triangle inequality, lower > upper, a zero axis, a broken capsule triplet, a
///   bad extension element, anything else urdfdom rejects, and whatever
///   ModelDescription::validate rejects.
ModelDescription readUrdf(const std::string& xml, const std::string& source);

/// Reads the URDF file at `path`; messages name `path` as the source.
/// @throws graspsim::InputError if the file cannot be read, or as readUrdf.
ModelDescription importUrdf(const std::string& path);

}  // namespace graspsim::model
