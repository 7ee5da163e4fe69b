#pragma once
/// @file
/// The point of a contact shape's surface nearest to a query point: what grasp planning and the
/// set-up check ask of an object ("how far is this fingertip from the surface, and which way
/// does the surface face there?").

#include "graspsim/simbody.h"

#include "graspsim/contact/contact_shape.h"

namespace graspsim::contact {

/// A query point's nearest surface point on a shape, everything in the shape frame S.
struct SurfacePoint {
    double distance = 0;      ///< signed distance from the query point to the surface (m), < 0 inside
    SimTK::Vec3 p_SP{0, 0, 0};  ///< the nearest surface point P (m)
    SimTK::UnitVec3 n_S;      ///< outward unit normal of the surface at P
};

/// Nearest surface point of `shape` to the point Q at p_SQ (m, in S). Exact for every shape.
/// Where the nearest point is not unique (the centre of a sphere, the axis of a capsule, a point
/// inside a box equally deep below several faces), one of them is chosen deterministically: the
/// +z pole for a sphere's centre, the direction +x for a capsule's axis, the face of the lowest
/// axis index among a box's equally deep faces (on the + side at a mid-plane), the side for a
/// point inside a cylinder equally deep below side and cap (+x on its axis), Eberly's case order
/// for an ellipsoid, the face of the lowest index among a convex mesh's equally deep faces.
/// The normal is that of the surface at P (so Q - P is along it).
SurfacePoint findSurfacePoint(const ContactShape& shape, const SimTK::Vec3& p_SQ);

}  // namespace graspsim::contact
