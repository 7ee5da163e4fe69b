#pragma once
/// @file
/// A convex polytope built from a closed, convex triangle mesh: the contact layer's view of a
/// mesh object. Immutable once built; ContactShape shares it through a shared_ptr, so copying a
/// shape is cheap.
///
/// Building merges coplanar triangles into faces (planes), keeps as edges only the mesh edges
/// between two faces of different planes (a box meshed with 12 triangles has 6 faces, 12 edges
/// and 8 vertices, like the box) and as vertices only the mesh vertices where three or more
/// planes meet. Everything is in the mesh's geometry frame S (m).

#include "graspsim/simbody.h"

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "graspsim/model/model_description.h"

namespace graspsim::contact {

/// Faces whose planes are within this (m) of the deepest one below a point count as equally
/// deep there (the tie rule of boxes, box_signed_distance.h, with the same tolerance).
constexpr double kPolytopeFaceTieTolerance = 1e-10;

/// A convex polytope (see the file comment).
class ConvexPolytope {
public:
    /// A face plane: the points x with dot(normal, x) <= offset are on its inner side.
    struct Face {
        SimTK::UnitVec3 normal;  ///< outward unit normal in S
        double offset = 0;       ///< dot(normal, x) on the plane (m)
    };
    /// An edge between two faces of different planes.
    struct Edge {
        int vertex0 = 0, vertex1 = 0;  ///< indices into getVertices()
        int face0 = 0, face1 = 0;      ///< indices into getFaces(), face0 < face1
    };
    /// A mesh triangle and the face (plane) it lies in (getTriangles() lists them by face).
    struct Triangle {
        std::array<SimTK::Vec3, 3> corners;
        int face = 0;
    };
    /// Signed distance and nearest-surface data of a point (see findSurface()).
    struct Surface {
        double distance = 0;       ///< signed distance (m), < 0 inside
        SimTK::UnitVec3 n_S;       ///< outward unit normal at the nearest surface point
        SimTK::Vec3 p_SP{0, 0, 0}; ///< a nearest surface point (m)
        std::vector<int> tiedFaces;  ///< inside: the equally deep faces counted, lowest index first
    };

    /// Builds the polytope of a closed, convex, outward-oriented triangle mesh.
    /// @param what names the mesh for messages ("geometry 'mug'").
    /// @throws graspsim::InputError naming `what` if the mesh has fewer than 4 vertices, an index
    ///         out of range, a degenerate triangle, an edge not shared by exactly two triangles
    ///         of opposite orientation (not closed), a non-positive volume (inverted normals),
    ///         or a vertex above a face plane by more than 1e-9 of its size (not convex).
    static std::shared_ptr<const ConvexPolytope> build(const model::TriangleMesh& mesh,
                                                       const std::string& what);

    const std::vector<SimTK::Vec3>& getVertices() const { return vertices_; }
    const std::vector<Face>& getFaces() const { return faces_; }
    const std::vector<Edge>& getEdges() const { return edges_; }
    const std::vector<Triangle>& getTriangles() const { return triangles_; }
    /// Radius (m) of the smallest sphere about S's origin holding every vertex.
    double getBoundingRadius() const { return boundingRadius_; }
    /// The edge between faces f0 and f1 (any order), or -1 if they share none.
    int findEdge(int f0, int f1) const;

    /// Exact signed distance (m) of p_S: inside, the largest plane distance (the depth below
    /// the nearest face plane, negated); outside, the Euclidean distance to the nearest
    /// triangle. Convex in p_S.
    double calcSignedDistance(const SimTK::Vec3& p_S) const;

    /// Signed distance, nearest surface point and outward normal at p_S. Outside, the normal is
    /// (p_S - nearest point) / distance. Inside, faces within kPolytopeFaceTieTolerance of the
    /// deepest share the normal (the normalized sum of their normals), as for boxes; of two
    /// opposite tied faces (a point on the mid-plane of a slab) only the one with the
    /// lexicographically greater normal counts (a box's + face). The nearest point is the
    /// projection onto the first tied face.
    Surface findSurface(const SimTK::Vec3& p_S) const;

private:
    void indexTrianglesByFace();
    // Euclidean distance from an outside point to the nearest triangle, and that point.
    double findOutsideDistance(const SimTK::Vec3& p_S, SimTK::Vec3* nearest) const;

    std::vector<SimTK::Vec3> vertices_;
    std::vector<Face> faces_;
    std::vector<Edge> edges_;
    std::vector<Triangle> triangles_;  // grouped by face
    std::vector<int> firstTriangle_;   // face f's triangles: [firstTriangle_[f], firstTriangle_[f + 1])
    double boundingRadius_ = 0;
};

}  // namespace graspsim::contact
