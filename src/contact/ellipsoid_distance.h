#pragma once
// The exact nearest point of an ellipsoid's surface to a point, by Eberly's robust bisection
// ("Distance from a Point to an Ellipse, an Ellipsoid, or a Hyperellipsoid", Geometric Tools,
// 2013): the nearest point x of the surface to y satisfies x_i = e_i^2 y_i / (t + e_i^2) for the
// root t of one monotone function, found to machine precision inside Eberly's bracket (by
// Newton steps where they stay inside it, bisection otherwise). Private to the
// contact layer. Everything is in the ellipsoid frame S, semi-axes e along x_S, y_S, z_S (m).

#include <simbody/Simbody.h>

namespace graspsim::contact {

/// Nearest surface point and signed distance of p_S (negative inside).
struct EllipsoidSurfacePoint {
    SimTK::Vec3 p_SP{0, 0, 0};  ///< nearest surface point (m)
    double distance = 0;        ///< signed distance |p_S - p_SP| (m), < 0 inside
};

/// Exact for any point, inside or outside. Where the nearest point is not unique (the centre,
/// points of the medial set inside), one is chosen deterministically by the algorithm's case
/// order.
EllipsoidSurfacePoint findEllipsoidSurfacePoint(const SimTK::Vec3& e, const SimTK::Vec3& p_S);

/// Outward unit normal of the ellipsoid at surface point p_SP: (x_i / e_i^2) normalized.
SimTK::UnitVec3 calcEllipsoidNormal(const SimTK::Vec3& e, const SimTK::Vec3& p_SP);

/// Gaussian-curvature radius 1 / sqrt(K) (m) at surface point p_SP: a b c |(x_i / e_i^2)|^2.
double calcEllipsoidCurvatureRadius(const SimTK::Vec3& e, const SimTK::Vec3& p_SP);

/// The point of the ellipsoid farthest along unit direction u_S: x_i = e_i^2 u_i / |e * u|.
SimTK::Vec3 findEllipsoidSupportPoint(const SimTK::Vec3& e, const SimTK::Vec3& u_S);

}  // namespace graspsim::contact
