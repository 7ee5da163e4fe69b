#pragma once
// Contacts where a box's corners or edges press into another solid: box vs box and box vs
// half-space. Private to the contact layer; shape_contact.cpp dispatches here.

#include <simbody/Simbody.h>

#include <vector>

#include "graspsim/contact/contact_shape.h"
#include "graspsim/contact/shape_contact.h"

namespace graspsim::contact {

/// Appends one contact per vertex of `box` (posed at X_GB) below the surface of the half-space
/// posed at X_GH; normals point from the box toward the half-space.
void appendBoxHalfSpaceContacts(const ContactShape& box, const SimTK::Transform& X_GB,
                                const SimTK::Transform& X_GH, std::vector<ContactPoint>& contacts);

/// Appends the contacts between boxes a (at X_GA) and b (at X_GB): vertices of each inside the
/// other, and edges of each whose deepest point inside the other is interior to the edge. An
/// edge-edge crossing, which both boxes' edges see, is counted once. Normals point from a to b.
void appendBoxBoxContacts(const ContactShape& a, const SimTK::Transform& X_GA,
                          const ContactShape& b, const SimTK::Transform& X_GB,
                          std::vector<ContactPoint>& contacts);

}  // namespace graspsim::contact
