#pragma once
// The signed distance of a point to a box, and the box's outward normal there. Private to the
// contact layer. Everything is in the box frame S, where the box is |x_i| <= h_i (m).

#include <simbody/Simbody.h>

namespace graspsim::contact {

/// Faces whose depths below a point differ by less than this (m) count as equally deep, and the
/// normal there is the normalized sum of their normals (see findBoxSurface()).
constexpr double kBoxFaceTieTolerance = 1e-10;

/// Signed distance (m) from p_S to the surface of the box with half-lengths h (negative
/// inside): Euclidean distance to the box outside, minus the depth below the nearest face
/// inside. Convex in p_S.
double calcBoxSignedDistance(const SimTK::Vec3& h, const SimTK::Vec3& p_S);

/// Signed distance and the outward unit normal at the point of the surface nearest to p_S.
struct BoxSurfacePoint {
    double distance = 0;           ///< signed distance (m), negative inside
    SimTK::UnitVec3 n_S;           ///< outward normal, in S
    int tiedAxisCount = 1;         ///< inside: how many faces (of different axes) are equally deep
    int tiedAxes[3] = {0, 0, 0};   ///< their axes, first tiedAxisCount entries
    int tiedSigns[3] = {1, 1, 1};  ///< their sides (+1 or -1)
};

/// Nearest surface point query. Outside, n_S = (p_S - closest point) / distance. Inside, the
/// nearest face per axis is the one on p_S's side; among the three, the shallowest (largest
/// |p_i| - h_i) wins, and faces within kBoxFaceTieTolerance of it share the normal: n_S is the
/// normalized sum of their outward normals.
BoxSurfacePoint findBoxSurface(const SimTK::Vec3& h, const SimTK::Vec3& p_S);

}  // namespace graspsim::contact
