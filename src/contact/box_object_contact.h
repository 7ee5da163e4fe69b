#pragma once
// Contacts between a box (a palm) and an object solid that is not a box: cylinder, ellipsoid or
// convex mesh. Private to the contact layer; shape_contact.cpp dispatches here, and
// shape_contact.h states the rules.

#include <simbody/Simbody.h>

#include <vector>

#include "graspsim/contact/contact_shape.h"
#include "graspsim/contact/shape_contact.h"

namespace graspsim::contact {

/// Appends the contacts between a box (at X_GB) and an object solid (at X_GS); normals point
/// from the box toward the solid.
///  - Each box vertex inside the solid, and each box edge whose deepest point inside the solid
///    is interior to the edge (the solid's exact SDF, minimized along the edge).
///  - Convex mesh: the same for the mesh's vertices and edges inside the box; an edge crossing
///    an edge of the other solid (deepest point equally deep below two adjacent faces) uses the
///    exact line-line depth and is counted once, exactly as box vs box (box_contact.h).
///  - Cylinder, ellipsoid: for each box face, the solid's deepest point below it (ellipsoid:
///    support point; cylinder: the deepest point of its side line facing the face, the middle
///    where that line lies flat, or the centre of a cap lying flat on the face), when that
///    face is the nearest face of the box there.
void appendBoxObjectContacts(const ContactShape& box, const SimTK::Transform& X_GB,
                             const ContactShape& solid, const SimTK::Transform& X_GS,
                             std::vector<ContactPoint>& contacts);

}  // namespace graspsim::contact
