#pragma once
// Contacts with the object solids that are not boxes (cylinder, ellipsoid, convex mesh): a
// swept sphere (fingertip, finger segment) against one, and one against a half-space (box vs
// these: box_object_contact.h). Private to the contact layer; shape_contact.cpp dispatches here, and
// shape_contact.h states the rules.

#include <simbody/Simbody.h>

#include <vector>

#include "graspsim/contact/contact_shape.h"
#include "graspsim/contact/shape_contact.h"
#include "swept_sphere_contact.h"

namespace graspsim::contact {

/// Hertz radius (m) of two curved surfaces in contact, 1 / (1/a + 1/b); a flat surface has
/// radius Infinity and leaves the other's.
double combineRadii(double a, double b);

/// Appends the contacts between a swept sphere and an object solid posed at X_GS, if any (one, or
/// for a capsule under CapsuleContact::Ends up to three); normals point from the swept sphere
/// toward the solid.
void appendSweptObjectContact(const SweptSphere& swept, const ContactShape& solid, const SimTK::Transform& X_GS,
                              CapsuleContact rule, std::vector<ContactPoint>& contacts);

/// Appends the contacts of an object solid (at X_GS) below the surface of a half-space (at
/// X_GH); normals point from the solid toward the half-space.
void appendObjectHalfSpaceContacts(const ContactShape& solid, const SimTK::Transform& X_GS,
                                   const SimTK::Transform& X_GH,
                                   std::vector<ContactPoint>& contacts);

}  // namespace graspsim::contact
