#pragma once
// Contacts of spheres and capsules, seen as swept spheres: a core (a point or a segment) plus a
// radius. Private to the contact layer; shape_contact.cpp dispatches here.

#include <simbody/Simbody.h>

#include <vector>

#include "graspsim/contact/contact_parameters.h"
#include "graspsim/contact/contact_shape.h"
#include "graspsim/contact/shape_contact.h"

namespace graspsim::contact {

/// Values (m) of a convex function within this of its minimum count as the minimum: where a
/// segment's signed distance is flat to this tolerance, the contact goes to the middle. Where a
/// flat stretch ends in a rounded rise (a capsule overhanging a box edge by d), the stretch
/// seems longer by about sqrt(2 d kFlatTolerance), moving the contact by half that (5 nm for
/// d = 5 mm); where it ends in a kink, by kFlatTolerance / slope.
constexpr double kFlatTolerance = 1e-14;

/// A sphere (p0_G == p1_G) or capsule (axis from p0_G to p1_G), in Ground (m).
struct SweptSphere {
    SimTK::Vec3 p0_G{0, 0, 0};
    SimTK::Vec3 p1_G{0, 0, 0};
    double radius = 0;
};

/// The core and radius of a sphere or capsule posed at X_GS.
SweptSphere makeSweptSphere(const ContactShape& shape, const SimTK::Transform& X_GS);

/// Appends the contact between swept spheres a and b, if any; its normal points from a to b.
void appendSweptSweptContact(const SweptSphere& a, const SweptSphere& b,
                             std::vector<ContactPoint>& contacts);

/// A point of a swept sphere's core, in the solid's frame S, with its signed distance to the solid
/// (m), the solid's outward normal there and the contact's Hertz radius (m).
struct CoreSurface {
    SimTK::Vec3 core_S{0, 0, 0};
    double distance = 0;
    SimTK::UnitVec3 n_S{0, 0, 1};
    double radius = 0;
};

/// Appends the contact of a swept sphere of `radius` at `surface`, `depthOffset` (m) shallower
/// than its penetration, if it is still a contact.
void appendCoreContact(const CoreSurface& surface, double radius, double depthOffset, const SimTK::Transform& X_GS,
                       std::vector<ContactPoint>& contacts);

/// Appends a capsule's contacts under CapsuleContact::Ends: each end within reach, with its own
/// depth, then the deepest core point with the deeper end's depth taken off (nothing where it is an
/// end, or no deeper than one).
void appendCoreEndContacts(const CoreSurface& end0, const CoreSurface& end1, const CoreSurface& deepest, double radius,
                           const SimTK::Transform& X_GS, std::vector<ContactPoint>& contacts);

/// Appends a swept sphere's contacts with a solid under `rule`, from its core's ends c0_S and c1_S
/// and the core point deepest in the solid, each turned into a CoreSurface by surfaceAt(p_S).
template <class SurfaceAt>
void appendCoreContacts(const SimTK::Vec3& c0_S, const SimTK::Vec3& c1_S, const SimTK::Vec3& deepest_S, double radius,
                        CapsuleContact rule, const SimTK::Transform& X_GS, SurfaceAt&& surfaceAt,
                        std::vector<ContactPoint>& contacts) {
    const CoreSurface deepest = surfaceAt(deepest_S);
    if (rule == CapsuleContact::Ends && c0_S != c1_S) {
        appendCoreEndContacts(surfaceAt(c0_S), surfaceAt(c1_S), deepest, radius, X_GS, contacts);
    } else {
        appendCoreContact(deepest, radius, 0, X_GS, contacts);
    }
}

/// Appends the contacts between a swept sphere and a box or half-space `solid` posed at X_GS, if
/// any (one, or for a capsule under CapsuleContact::Ends up to three); normals point from the swept
/// sphere toward the solid.
void appendSweptSolidContact(const SweptSphere& swept, const ContactShape& solid, const SimTK::Transform& X_GS,
                             CapsuleContact rule, std::vector<ContactPoint>& contacts);

}  // namespace graspsim::contact
