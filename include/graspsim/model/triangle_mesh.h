#pragma once
/// @file
/// Properties of a closed triangle mesh (model::TriangleMesh): its volume, centroid and inertia
/// by the divergence theorem, its topology and convexity checks, and the signed distance from a
/// point to a convex mesh. Units: metres in, SI out.

#include "graspsim/model/geometry_inertia.h"
#include "graspsim/model/model_description.h"

#include <optional>
#include <utility>

namespace graspsim::model {

/// Volume (m^3), centroid (m, mesh frame) and central inertia (kg m^2, mesh frame axes) of the
/// solid the mesh encloses at unit density, summed over the signed tetrahedra that each triangle
/// makes with the origin (Tonon 2004; exact for any closed, consistently oriented mesh). Products
/// of inertia are kept: the mesh's axes are not rotated to principal axes. The volume is negative
/// when the triangles are ordered clockwise seen from outside (inverted normals).
MassProperties calcMeshMassProperties(const TriangleMesh& mesh);

/// An edge (pair of vertex indices, ascending) not shared by exactly two triangles, or nothing
/// when every edge is; a closed mesh has none.
std::optional<std::pair<int, int>> findOpenEdge(const TriangleMesh& mesh);

/// Volume of the convex hull of the mesh's vertices (m^3), by qhull.
/// @throws graspsim::InputError (with `source`) when the vertices are flat or qhull fails.
double calcConvexHullVolume(const TriangleMesh& mesh, const std::string& source);

/// Signed distance (m) from point P to the surface of a closed convex mesh, positive outside:
/// outside, the distance to the nearest triangle; inside, minus the distance to the nearest face plane.
double calcConvexMeshDistance(const TriangleMesh& mesh, const Vec3& p_MP);

/// Outward unit normal of the triangle whose plane is farthest in front of P (the face nearest
/// to P from inside, the face P is most in front of from outside).
Vec3 findConvexMeshNormal(const TriangleMesh& mesh, const Vec3& p_MP);

}  // namespace graspsim::model
