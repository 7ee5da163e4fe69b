#pragma once
/// @file
/// Reads a closed convex triangle mesh from an STL (ASCII or binary) or OBJ file, for an
/// object's geometry. Reading is done by assimp (Debian's libassimp); graspsim checks the result.

#include "graspsim/model/model_description.h"

#include <string>

namespace graspsim::model {

/// Relative slack allowed between a mesh's volume and its convex hull's before the mesh counts
/// as not convex: enough for coordinates printed to six digits, far below any real dent.
constexpr double kConvexVolumeTolerance = 1e-6;

/// Reads `path` and returns its triangles with `scale` (per axis of the file's frame, each > 0)
/// applied, vertices of equal position joined, in the file's own frame (no centring).
///
/// The mesh must be: a readable STL or OBJ file with at least one triangle; closed (every edge
/// shared by exactly two triangles); oriented outward (positive enclosed volume); convex (its
/// volume equals its convex hull's, by qhull, within kConvexVolumeTolerance).
/// @param place where the path was given, for messages (e.g. "ball.yaml:9: object.mesh").
/// @throws graspsim::InputError, one line naming `place`, the path, what is wrong and what is accepted.
TriangleMesh readMeshFile(const std::string& path, const Vec3& scale, const std::string& place);

/// The same for a file's bytes already in memory: `format` is "stl" or "obj" (the extension),
/// `what` names it in messages (place and path). readMeshFile reads the file and calls this.
/// @throws graspsim::InputError as readMeshFile.
TriangleMesh parseMeshBytes(const std::string& bytes, const std::string& format, const Vec3& scale,
                            const std::string& what);

/// Same checks for a mesh already in memory (`what` names it in messages: place and path).
/// @throws graspsim::InputError as readMeshFile.
void checkSolidConvexMesh(const TriangleMesh& mesh, const std::string& what);

}  // namespace graspsim::model
