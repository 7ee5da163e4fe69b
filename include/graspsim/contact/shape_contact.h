#pragma once
/// @file
/// Contact geometry between two shapes: where two posed shapes overlap, how deep, and along
/// which normal. Pure functions of the shapes and their poses (no Simbody state).
///
/// Everything is exact signed-distance geometry. Spheres and capsules are treated as "swept
/// spheres": a core (point or segment) plus a radius. Boxes and half-spaces are solids with a
/// signed distance function (SDF, negative inside). The supported pairs, in either order:
///
///  - sphere/capsule vs sphere/capsule: one contact, between the closest points of the two
///    cores (closed form);
///  - sphere/capsule vs box or half-space: one contact, at the core point where the solid's SDF
///    is least; for a capsule under CapsuleContact::Ends (compliant contact's choice), one at each
///    core end within reach and one at a deeper interior minimum, less the deeper end's depth;
///  - box vs box: each vertex of either box inside the other, and each edge of either box whose
///    deepest point inside the other is interior to the edge (an edge crossing the other box's
///    edge, or lying across one of its faces);
///  - box vs half-space: each vertex below the surface.
///
///  - sphere/capsule vs cylinder, ellipsoid or convex mesh: one contact, at the core point
///    where the solid's exact SDF is least (as for boxes, CapsuleContact::Ends too);
///  - box vs cylinder, ellipsoid or convex mesh: each box vertex inside the solid and each box
///    edge whose deepest point inside it is interior to the edge; for a convex mesh also its
///    vertices and edges inside the box, with the box-box edge-edge rule (so a mesh of a box
///    gives the box's contacts); for a cylinder or ellipsoid, for each box face the solid's
///    deepest point below it where that face is the nearest (box_object_contact.h);
///  - cylinder, ellipsoid or convex mesh vs half-space: the mesh's vertices below the surface,
///    the ellipsoid's lowest point, the cylinder's lowest side line (its middle when lying flat)
///    or lower cap centre.
///
/// Half-space vs half-space and two of cylinder, ellipsoid, convex mesh are rejected (the hand
/// is made of spheres, capsules and boxes). Method, choices and costs: docs/contact.md.
///
/// Depth, point and normal of one contact: with the deepest core point c (or vertex, or edge
/// point), its signed distance d to the other solid and that solid's outward normal o there,
/// depth = r - d (r the swept radius, 0 for box features), normal -o from the penetrating shape
/// toward the solid (negated when the solid is A), point midway between the two surface points
/// c - d o and c - r o.
///
/// Rules that keep contacts from jumping:
///  - Along a segment (capsule axis, box edge) the SDF of a convex solid is convex; we minimize
///    it by a bracketing search to 1e-12 of the segment. Where it is flat (to 1e-14 m) over an
///    interval, because the segment lies parallel to a face, the contact sits at the middle of
///    that interval. Two parallel capsules touch at the middle of their overlap.
///  - Inside a box, a point equally deep (to 1e-10 m) below two or three faces gets the
///    normalized sum of those faces' normals.
///  - A box edge whose deepest point inside the other box lies below two adjacent faces crosses
///    the edge where they meet. Its contact uses the exact line-line geometry of the two edges
///    (normal along their cross product, depth = gap between the lines; the SDF depth would be
///    up to sqrt 2 too small), and it is counted once although both boxes' edges see it.
///  - A box edge whose deepest point is one of its ends adds nothing: that end is a vertex,
///    already counted. (For two equal, exactly aligned boxes a vertex of each sits at the same
///    place, so such a corner counts twice.)
///  - Limitation: a box feature pushed more than halfway through the other box's thinnest
///    dimension (or a capsule core through a box) is equally deep below two opposite faces; the
///    normal then follows the side of the mid-plane the point falls on, so it may flip, and the
///    two argument orders may disagree. Compliant contact never gets near such depths.
///
/// Effective Hertz radius R (m) of each contact: 1/R = 1/R_A + 1/R_B over the curved surfaces
/// involved, with a flat face (box face, half-space) contributing nothing. A swept sphere against
/// a box or half-space therefore has R = its radius (box edges and corners under a sphere are
/// treated like the faces they bound); a box vertex or edge pressing into a face has R =
/// ContactShape::cornerRadius (see kDefaultBoxCornerRadius); an edge-edge contact combines the
/// two boxes' corner radii. Object solids: a cylinder's side has its radius (the curvature in
/// the cross-section; its caps are flat, its rims count like the faces they bound), an
/// ellipsoid the Gaussian-curvature radius 1/sqrt(K) at the contact point, a mesh's faces are
/// flat and its edges and vertices pressing into a box have its cornerRadius; a cylinder's cap
/// lying flat on a box face has the cylinder's radius.
///
/// Symmetry: findContacts(b, X_GB, a, X_GA) returns the same contacts as findContacts(a, X_GA,
/// b, X_GB) with every normal negated (box-box contacts possibly in another order).

#include "graspsim/simbody.h"

#include <vector>

#include "graspsim/contact/contact_parameters.h"
#include "graspsim/contact/contact_shape.h"
#include "graspsim/model/model_description.h"

namespace graspsim::contact {

/// One point contact between shape A and shape B, in Ground G.
struct ContactPoint {
    SimTK::Vec3 p_G{0, 0, 0};  ///< contact point, midway between the two surfaces along n_G (m)
    SimTK::UnitVec3 n_G;       ///< unit normal, pointing from shape A toward shape B
    double depth = 0;          ///< penetration depth along n_G, > 0 (m)
    double radius = 0;         ///< effective Hertz radius of curvature (m), see the file comment
};

/// Contacts between shape `a` posed at X_GA (pose of A's shape frame in Ground) and shape `b`
/// at X_GB. Empty when they do not overlap; touching (depth 0) is not a contact.
/// @throws graspsim::InputError for two half-spaces or two object solids (cylinder, ellipsoid,
///         convex mesh).
std::vector<ContactPoint> findContacts(const ContactShape& a, const SimTK::Transform& X_GA,
                                       const ContactShape& b, const SimTK::Transform& X_GB);

/// As above, appending to `contacts` (so a caller can reuse one buffer without allocating), with
/// `rule` choosing where a capsule touches a box, half-space or object solid (CapsuleContact;
/// findContacts() uses Deepest).
void appendContacts(const ContactShape& a, const SimTK::Transform& X_GA, const ContactShape& b,
                    const SimTK::Transform& X_GB, std::vector<ContactPoint>& contacts,
                    CapsuleContact rule = CapsuleContact::Deepest);

/// Contacts between two model geometries; X_GA and X_GB are the poses of the geometry frames in
/// Ground (the geometries' own X_BG are not used here: compose X_GA = X_GBody * X_BG yourself).
/// @throws graspsim::InputError for a Mesh without loaded triangles, sizes ContactShape rejects,
///         or a pair findContacts() rejects.
std::vector<ContactPoint> findContacts(const model::Geometry& a, const SimTK::Transform& X_GA,
                                       const model::Geometry& b, const SimTK::Transform& X_GB);

}  // namespace graspsim::contact
