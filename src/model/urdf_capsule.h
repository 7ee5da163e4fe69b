#pragma once
// Capsules in URDF, which has none: each capsule is written as three collision elements whose
// union is exactly the capsule, so other URDF readers see the right shape, and read back as one.
//
//   <name>__capsule_cylinder  cylinder of the capsule's radius and length at the capsule pose G
//   <name>__capsule_cap_pos   sphere of the same radius centred at G * (0, 0, +length/2)
//   <name>__capsule_cap_neg   sphere of the same radius centred at G * (0, 0, -length/2)

#include "urdf_source.h"

#include "graspsim/model/model_description.h"

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace graspsim::model {

inline constexpr std::string_view kCapsuleCylinderSuffix = "__capsule_cylinder";
inline constexpr std::string_view kCapsuleCapPosSuffix = "__capsule_cap_pos";
inline constexpr std::string_view kCapsuleCapNegSuffix = "__capsule_cap_neg";

/// How far (m) a cap centre may sit from the cylinder end, and cap and cylinder radii may differ.
inline constexpr double kCapsuleTolerance = 1e-9;

/// True when `name` ends in one of the three suffixes, which the encoding reserves.
bool hasCapsuleSuffix(const std::string& name);

/// The cylinder and the two end spheres (named with the suffixes) whose union is `capsule`.
std::array<Geometry, 3> splitCapsule(const Geometry& capsule);

/// One link's collision geometry, in file order, with each triplet replaced by the capsule it
/// encodes (named without the suffix, at the cylinder's place in the order).
/// @param line line of the <link> element, for messages.
/// @throws graspsim::InputError for an incomplete or repeated triplet, a part of the wrong shape,
///   radii that differ, or caps that are not at the cylinder ends (kCapsuleTolerance).
std::vector<Geometry> mergeCapsuleTriplets(const std::vector<Geometry>& geometry, const std::string& linkName, int line,
                                           const UrdfSource& source);

}  // namespace graspsim::model
