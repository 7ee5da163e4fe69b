#pragma once
// Simbody's rules on a body's mass properties, which are stricter than a rigid body's: part of
// ModelDescription::validate, so that a URDF that breaks them is refused naming its file.

#include "graspsim/model/model_description.h"

#include <string>

namespace graspsim::model {

/// Checks that Simbody will accept `body`'s mass properties. Simbody keeps the inertia about the
/// body origin and recovers the central inertia from it when the topology is realized; a mass
/// centre far from the origin next to the body's size cancels the central inertia away in
/// rounding, and the recovered central inertia must obey Simbody's triangle and product rules
/// within its slop, sqrt(eps) max(trace, 1) (this check keeps half of it). Massless bodies pass.
/// @throws graspsim::InputError "<source>: link '<name>' <field> = <value> is not accepted; ..."
///   naming the centre of mass (m) with m |p|^2 and its limit (kg m^2), or the inertia (kg m^2,
///   ixx iyy izz ixy ixz iyz about the mass centre in the link frame) with the rule it breaks.
void checkMassPropertiesForSimbody(const std::string& source, const Body& body);

}  // namespace graspsim::model
