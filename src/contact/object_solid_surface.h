#pragma once
// Signed distance, nearest surface point, outward normal and surface curvature of the object
// solids that are not boxes: cylinders (closed form), ellipsoids (ellipsoid_distance.h) and
// convex meshes (ConvexPolytope). Private to the contact layer; contact and surface_point use
// it. Everything is in the solid's frame S (m).

#include <simbody/Simbody.h>

#include "graspsim/contact/contact_shape.h"

namespace graspsim::contact {

/// Tolerance (m) within which a point inside a cylinder counts as equally deep below its side
/// and a cap (the box rule, box_signed_distance.h): the normal is then the normalized sum.
constexpr double kCylinderTieTolerance = 1e-10;

/// What contact needs to know of a solid's surface at the point nearest to a query point.
struct ObjectSurface {
    double distance = 0;        ///< signed distance (m), < 0 inside
    SimTK::UnitVec3 n_S;        ///< outward unit normal
    SimTK::Vec3 p_SP{0, 0, 0};  ///< nearest surface point
    /// Hertz radius of the surface there (m): a cylinder's radius on its side, the
    /// Gaussian-curvature radius of an ellipsoid, Infinity on flat faces and on edges, rims and
    /// corners (which under a swept sphere count like the faces they bound, as for boxes).
    double curvatureRadius = SimTK::Infinity;
    int tiedFaceCount = 1;       ///< convex mesh, inside: number of equally deep faces
    int tiedFaces[2] = {0, 0};   ///< convex mesh: the first two of them
};

/// Exact signed distance of p_S to a Cylinder, Ellipsoid or ConvexMesh (convex in p_S).
double calcObjectSignedDistance(const ContactShape& solid, const SimTK::Vec3& p_S);

/// Surface query for a Cylinder, Ellipsoid or ConvexMesh (see ObjectSurface). At a cylinder's
/// axis the radial direction is +x_S; inside, the cylinder's side and cap tie within
/// kCylinderTieTolerance, a mesh's faces within kPolytopeFaceTieTolerance.
ObjectSurface findObjectSurface(const ContactShape& solid, const SimTK::Vec3& p_S);

/// Whether the shape is one of the solids above.
bool isObjectSolid(const ContactShape& shape);

}  // namespace graspsim::contact
