#pragma once
// A URDF <inertial> as a body's mass properties, with the physical checks a URDF file needs.

#include "urdf_source.h"

#include "graspsim/model/model_description.h"

#include <urdf_model/link.h>

#include <array>

namespace graspsim::model {

/// Sets body.mass, body.p_BCm and body.inertia from a URDF <inertial>. Its origin xyz is the
/// centre of mass in the link frame B; its inertia is given about the centre of mass in the
/// inertial frame I, rotated from B by the origin's rpy, so I_B = R_BI I_I R_BI^T.
/// @param line line of the <link> element, for messages.
/// @throws graspsim::InputError for a negative or non-finite mass or inertia component, and,
///   for a link with mass, an inertia whose principal moments are not all positive or break
///   the triangle inequality (the largest may not exceed the sum of the other two).
void setBodyMassProperties(const urdf::Inertial& inertial, int line, const UrdfSource& source, Body& body);

}  // namespace graspsim::model
