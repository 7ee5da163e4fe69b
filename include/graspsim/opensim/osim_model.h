#pragma once
/// @file
/// Writing a ModelDescription as an OpenSim 4 model file (.osim, XML document version 40000).
///
/// The mapping, chosen so that OpenSim poses every body exactly where graspsim does:
/// - Each body B is an OpenSim `Body` with `mass` (kg), `mass_center` = p_BCm (m, in B) and
///   `inertia` = the central inertia in B as Ixx Iyy Izz Ixy Ixz Iyz (kg m^2; the products are the
///   matrix's off-diagonal entries, graspsim's and URDF's convention). Virtual bodies of multi-DOF
///   joint chains stay massless bodies, as in the URDF.
/// - A revolute or continuous joint J is a `PinJoint`, which turns about the common z axis of its
///   two offset frames: the parent offset frame is X_PJ * R_JA and the child offset frame is R_JA,
///   where R_JA turns z onto the joint axis, so X_PC(q) = X_PJ * Rot(axis, q). A prismatic joint is
///   a `SliderJoint` (x axis, R_JA turns x onto the axis); a fixed joint is a `WeldJoint`.
/// - The root body is welded to ground at X_GR (`WeldJoint` "ground_<root>").
/// - Each joint has one `Coordinate` named after the joint: `range` = [lower, upper] (rad or m;
///   +-2 pi for continuous joints), `default_value` = 0 clamped into the range, `clamped` for
///   limited joints. Coordinate names are the joint names of trajectory.csv and motion.mot.
/// - Offset frames' `orientation` is OpenSim's frame-fixed x-y-z sequence: R = Rx(a) Ry(b) Rz(c).
/// - Geometry is attached through a `PhysicalOffsetFrame` per shape in the body's `components`:
///   `Sphere` (radius), `Brick` (half_lengths), `Cylinder` (radius, half_height; OpenSim's
///   cylinders lie along y, graspsim's along z, so the frame adds Rx(pi/2)), a capsule as a
///   cylinder and two end spheres, `Mesh` (mesh_file as given).
/// - Gravity is 0 -9.81 0 (m/s^2), graspsim's default (system_options.h): its ground frame has y up.
/// Numbers are written with 17 significant digits, so they read back to the same double.

#include "graspsim/model/model_description.h"

#include <array>
#include <string>

namespace graspsim::opensim {

/// The .osim text of `model`.
/// @throws graspsim::InputError if `model` fails ModelDescription::validate or has a body named
///   "ground" (OpenSim's name for the ground frame).
std::string writeOsim(const model::ModelDescription& model);

/// OpenSim's orientation angles (rad) of a rotation: R = Rx(a) Ry(b) Rz(c) (frame-fixed x-y-z).
/// At b = +-pi/2 (gimbal lock), a is 0.
/// @param R row-major, orthonormal.
std::array<double, 3> calcBodyXyzAngles(const std::array<double, 9>& R);

}  // namespace graspsim::opensim
