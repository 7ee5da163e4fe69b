#include "graspsim/contact/convex_polytope.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <sstream>
#include <tuple>
#include <utility>

#include "graspsim/error.h"

namespace graspsim::contact {

namespace {

[[noreturn]] void throwBadMesh(const std::string& what, const std::string& problem) {
    throw InputError(what + ": mesh " + problem);
}

// Mesh vertices with exactly equal coordinates become one (an STL file repeats every vertex per
// triangle); returns the welded vertices and the triangles re-indexed onto them.
std::pair<std::vector<SimTK::Vec3>, std::vector<std::array<int, 3>>> weldVertices(
    const model::TriangleMesh& mesh, const std::string& what) {
    std::map<std::array<double, 3>, int> index;
    std::vector<int> welded(mesh.vertices.size());
    std::vector<SimTK::Vec3> vertices;
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        const model::Vec3& v = mesh.vertices[i];
        if (!(std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]))) {
            throwBadMesh(what, "vertex " + std::to_string(i) + " is not finite");
        }
        const auto [it, added] = index.emplace(std::array<double, 3>{v[0], v[1], v[2]},
                                               static_cast<int>(vertices.size()));
        if (added) vertices.emplace_back(v[0], v[1], v[2]);
        welded[i] = it->second;
    }
    std::vector<std::array<int, 3>> triangles;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        std::array<int, 3> tri{};
        for (int k = 0; k < 3; ++k) {
            const int i = mesh.triangles[t][k];
            if (i < 0 || i >= static_cast<int>(welded.size())) {
                throwBadMesh(what, "triangle " + std::to_string(t) + " has vertex index " +
                                       std::to_string(i) + " out of range");
            }
            tri[k] = welded[i];
        }
        triangles.push_back(tri);
    }
    return {vertices, triangles};
}

// Each undirected edge (i < j) and the triangles on its two sides: the one where it runs i to j
// and the one where it runs j to i. A closed, consistently oriented mesh has both, once each.
std::map<std::pair<int, int>, std::array<int, 2>> findEdgeTriangles(
    const std::vector<std::array<int, 3>>& triangles, const std::string& what) {
    std::map<std::pair<int, int>, std::array<int, 2>> edges;
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        for (int k = 0; k < 3; ++k) {
            const int i = triangles[t][k], j = triangles[t][(k + 1) % 3];
            auto& sides = edges.try_emplace({std::min(i, j), std::max(i, j)},
                                            std::array<int, 2>{-1, -1})
                              .first->second;
            int& side = sides[i < j ? 0 : 1];
            if (side >= 0) {
                throwBadMesh(what, "is not closed or not consistently oriented (edge between "
                                   "vertices " + std::to_string(i) + " and " +
                                   std::to_string(j) + " appears twice in the same direction)");
            }
            side = static_cast<int>(t);
        }
    }
    for (const auto& [edge, sides] : edges) {
        if (sides[0] < 0 || sides[1] < 0) {
            throwBadMesh(what, "is not closed (edge between vertices " +
                                   std::to_string(edge.first) + " and " +
                                   std::to_string(edge.second) + " has one triangle)");
        }
    }
    return edges;
}

int findRoot(std::vector<int>& parent, int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

// Closest point to p on triangle (a, b, c) (Ericson, Real-Time Collision Detection, 5.1.5).
SimTK::Vec3 findClosestPointOnTriangle(const SimTK::Vec3& p, const SimTK::Vec3& a,
                                       const SimTK::Vec3& b, const SimTK::Vec3& c) {
    const SimTK::Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = SimTK::dot(ab, ap), d2 = SimTK::dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return a;
    const SimTK::Vec3 bp = p - b;
    const double d3 = SimTK::dot(ab, bp), d4 = SimTK::dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
    const SimTK::Vec3 cp = p - c;
    const double d5 = SimTK::dot(ab, cp), d6 = SimTK::dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
        return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
    }
    const double denominator = 1 / (va + vb + vc);
    return a + (vb * denominator) * ab + (vc * denominator) * ac;
}

// The welded mesh, checked closed and consistently oriented, with what each step below needs.
struct WeldedMesh {
    std::vector<SimTK::Vec3> vertices;
    std::vector<std::array<int, 3>> triangles;
    std::map<std::pair<int, int>, std::array<int, 2>> edgeTriangles;
    double size = 0;  // twice the largest vertex distance from the origin (m)
    std::string what;
};

// Each triangle's area-weighted normal; throws for a degenerate triangle or a mesh that does not
// enclose a positive volume (inside out).
std::vector<SimTK::Vec3> calcTriangleNormals(const WeldedMesh& m) {
    std::vector<SimTK::Vec3> normals;
    double volume = 0;
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
        const SimTK::Vec3 &a = m.vertices[m.triangles[t][0]], &b = m.vertices[m.triangles[t][1]],
                          &c = m.vertices[m.triangles[t][2]];
        const SimTK::Vec3 n = SimTK::cross(b - a, c - a);
        if (!(n.norm() > 1e-12 * m.size * m.size)) {
            throwBadMesh(m.what, "triangle " + std::to_string(t) + " is degenerate (zero area)");
        }
        normals.push_back(n);
        volume += SimTK::dot(a, SimTK::cross(b, c)) / 6;
    }
    if (!(volume > 0)) {
        std::ostringstream message;
        message << "encloses volume " << volume
                << " m^3; its triangles must wind counter-clockwise seen from outside (are the "
                   "normals inverted?)";
        throwBadMesh(m.what, message.str());
    }
    return normals;
}

// Groups coplanar neighbouring triangles into faces (on a convex solid every plane meets it in
// one face); each face takes the plane of its largest triangle (exact for axis-aligned meshes).
// Returns the face of each triangle and appends the faces.
std::vector<int> groupFaces(const WeldedMesh& m, const std::vector<SimTK::Vec3>& normals,
                            std::vector<ConvexPolytope::Face>& faces) {
    std::vector<int> parent(m.triangles.size());
    std::iota(parent.begin(), parent.end(), 0);
    const auto isCoplanar = [&](int s, int t) {
        const SimTK::Vec3 ns = normals[s] / normals[s].norm(), nt = normals[t] / normals[t].norm();
        const SimTK::Vec3 between = m.vertices[m.triangles[t][0]] - m.vertices[m.triangles[s][0]];
        return SimTK::dot(ns, nt) > 1 - 1e-12 && std::abs(SimTK::dot(ns, between)) <= 1e-12 * m.size;
    };
    for (const auto& [edge, sides] : m.edgeTriangles) {
        if (isCoplanar(sides[0], sides[1])) parent[findRoot(parent, sides[0])] = findRoot(parent, sides[1]);
    }
    std::map<int, int> faceOfRoot, largestOfRoot;
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
        auto [it, added] = largestOfRoot.emplace(findRoot(parent, static_cast<int>(t)), static_cast<int>(t));
        if (!added && normals[t].norm() > normals[it->second].norm()) it->second = static_cast<int>(t);
    }
    for (const auto& [root, largest] : largestOfRoot) {
        ConvexPolytope::Face face;
        face.normal = SimTK::UnitVec3(normals[largest]);
        face.offset = SimTK::dot(face.normal, m.vertices[m.triangles[largest][0]]);
        faceOfRoot[root] = static_cast<int>(faces.size());
        faces.push_back(face);
    }
    std::vector<int> faceOfTriangle(m.triangles.size());
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
        faceOfTriangle[t] = faceOfRoot[findRoot(parent, static_cast<int>(t))];
    }
    return faceOfTriangle;
}

// Throws if a vertex lies above a face plane by more than 1e-9 of the mesh size.
void checkConvex(const WeldedMesh& m, const std::vector<ConvexPolytope::Face>& faces) {
    for (const ConvexPolytope::Face& face : faces) {
        for (std::size_t v = 0; v < m.vertices.size(); ++v) {
            const double above = SimTK::dot(face.normal, m.vertices[v]) - face.offset;
            if (above > 1e-9 * m.size) {
                std::ostringstream message;
                message << "is not convex (vertex " << v << " lies " << above
                        << " m above the plane of a face); use its convex hull";
                throwBadMesh(m.what, message.str());
            }
        }
    }
}

// For each welded vertex, whether three or more face planes meet there (a polytope vertex).
std::vector<bool> findCorners(const WeldedMesh& m, const std::vector<int>& faceOfTriangle) {
    std::vector<std::vector<int>> facesAtVertex(m.vertices.size());
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
        for (int k = 0; k < 3; ++k) facesAtVertex[m.triangles[t][k]].push_back(faceOfTriangle[t]);
    }
    std::vector<bool> corner(m.vertices.size());
    for (std::size_t v = 0; v < m.vertices.size(); ++v) {
        std::vector<int>& faces = facesAtVertex[v];
        std::sort(faces.begin(), faces.end());
        corner[v] = std::unique(faces.begin(), faces.end()) - faces.begin() >= 3;
    }
    return corner;
}

}  // namespace

std::shared_ptr<const ConvexPolytope> ConvexPolytope::build(const model::TriangleMesh& mesh,
                                                            const std::string& what) {
    WeldedMesh m;
    std::tie(m.vertices, m.triangles) = weldVertices(mesh, what);
    m.what = what;
    if (m.vertices.size() < 4 || m.triangles.size() < 4) {
        throwBadMesh(what, "has " + std::to_string(m.vertices.size()) + " distinct vertices and " +
                               std::to_string(m.triangles.size()) +
                               " triangles; a closed solid needs at least 4 of each");
    }
    auto polytope = std::make_shared<ConvexPolytope>();
    for (const SimTK::Vec3& v : m.vertices) {
        polytope->boundingRadius_ = std::max(polytope->boundingRadius_, v.norm());
    }
    m.size = 2 * polytope->boundingRadius_;
    m.edgeTriangles = findEdgeTriangles(m.triangles, what);
    const std::vector<int> faceOfTriangle = groupFaces(m, calcTriangleNormals(m), polytope->faces_);
    checkConvex(m, polytope->faces_);
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
        const std::array<int, 3>& i = m.triangles[t];
        polytope->triangles_.push_back(
            {{m.vertices[i[0]], m.vertices[i[1]], m.vertices[i[2]]}, faceOfTriangle[t]});
    }
    polytope->indexTrianglesByFace();
    // Edges between faces of different planes, between polytope vertices. An edge end where
    // only two planes meet (a vertex splitting a straight edge) is not a polytope vertex; such
    // edge pieces are left out.
    const std::vector<bool> corner = findCorners(m, faceOfTriangle);
    std::vector<int> newIndex(m.vertices.size(), -1);
    for (std::size_t v = 0; v < m.vertices.size(); ++v) {
        if (!corner[v]) continue;
        newIndex[v] = static_cast<int>(polytope->vertices_.size());
        polytope->vertices_.push_back(m.vertices[v]);
    }
    for (const auto& [edge, sides] : m.edgeTriangles) {
        const int f0 = faceOfTriangle[sides[0]], f1 = faceOfTriangle[sides[1]];
        if (f0 == f1 || newIndex[edge.first] < 0 || newIndex[edge.second] < 0) continue;
        polytope->edges_.push_back(
            {newIndex[edge.first], newIndex[edge.second], std::min(f0, f1), std::max(f0, f1)});
    }
    return polytope;
}

void ConvexPolytope::indexTrianglesByFace() {
    // Grouped by face, so that a distance query visits only the faces it is above.
    std::stable_sort(triangles_.begin(), triangles_.end(),
                     [](const Triangle& a, const Triangle& b) { return a.face < b.face; });
    firstTriangle_.assign(faces_.size() + 1, 0);
    for (const Triangle& t : triangles_) ++firstTriangle_[t.face + 1];
    for (std::size_t f = 0; f < faces_.size(); ++f) firstTriangle_[f + 1] += firstTriangle_[f];
}

int ConvexPolytope::findEdge(int f0, int f1) const {
    const int lo = std::min(f0, f1), hi = std::max(f0, f1);
    for (std::size_t e = 0; e < edges_.size(); ++e) {
        if (edges_[e].face0 == lo && edges_[e].face1 == hi) return static_cast<int>(e);
    }
    return -1;
}

double ConvexPolytope::findOutsideDistance(const SimTK::Vec3& p_S, SimTK::Vec3* nearest) const {
    // The nearest point lies on a face whose plane p_S is above (the vector from it to p_S is
    // in the normal cone there, so it has a positive component along one of the faces meeting
    // there), and no point of a face is nearer than its plane: so only the triangles of faces
    // p_S is above by less than the best distance so far are searched. Near the surface they
    // are few.
    double best = SimTK::Infinity;
    for (std::size_t f = 0; f < faces_.size(); ++f) {
        const double above = SimTK::dot(faces_[f].normal, p_S) - faces_[f].offset;
        if (above <= 0 || above >= best) continue;
        for (int i = firstTriangle_[f]; i < firstTriangle_[f + 1]; ++i) {
            const Triangle& t = triangles_[i];
            const SimTK::Vec3 q = findClosestPointOnTriangle(p_S, t.corners[0], t.corners[1], t.corners[2]);
            const double distance = (p_S - q).norm();
            if (distance < best) {
                best = distance;
                if (nearest) *nearest = q;
            }
        }
    }
    return best;
}

double ConvexPolytope::calcSignedDistance(const SimTK::Vec3& p_S) const {
    double deepest = -SimTK::Infinity;
    for (const Face& face : faces_) {
        deepest = std::max(deepest, SimTK::dot(face.normal, p_S) - face.offset);
    }
    if (deepest <= 0) return deepest;
    return findOutsideDistance(p_S, nullptr);
}

ConvexPolytope::Surface ConvexPolytope::findSurface(const SimTK::Vec3& p_S) const {
    Surface surface;
    double deepest = -SimTK::Infinity;
    for (const Face& face : faces_) {
        deepest = std::max(deepest, SimTK::dot(face.normal, p_S) - face.offset);
    }
    if (deepest > 0) {
        surface.distance = findOutsideDistance(p_S, &surface.p_SP);
        surface.n_S = SimTK::UnitVec3((p_S - surface.p_SP) / surface.distance, true);
        return surface;
    }
    surface.distance = deepest;
    std::vector<int> tied;
    std::vector<double> above;  // plane distance of each tied face
    for (std::size_t f = 0; f < faces_.size(); ++f) {
        const double d = SimTK::dot(faces_[f].normal, p_S) - faces_[f].offset;
        if (d >= deepest - kPolytopeFaceTieTolerance) {
            tied.push_back(static_cast<int>(f));
            above.push_back(d);
        }
    }
    // Of two opposite faces (a point near the mid-plane of a slab) only the nearer counts, as
    // for boxes; exactly on the mid-plane the one whose normal is lexicographically greater
    // (a box's + face).
    SimTK::Vec3 sum(0);
    for (std::size_t i = 0; i < tied.size(); ++i) {
        const SimTK::Vec3& n = faces_[tied[i]].normal.asVec3();
        bool dropped = false;
        for (std::size_t j = 0; j < tied.size(); ++j) {
            const SimTK::Vec3& m = faces_[tied[j]].normal.asVec3();
            if (!(SimTK::dot(n, m) < -1 + 1e-12)) continue;
            dropped = dropped || above[j] > above[i] ||
                      (above[j] == above[i] &&
                       std::lexicographical_compare(&n[0], &n[0] + 3, &m[0], &m[0] + 3));
        }
        const int f = tied[i];
        if (dropped) continue;
        surface.tiedFaces.push_back(f);
        sum += n;
    }
    const Face& first = faces_[surface.tiedFaces.front()];
    surface.p_SP = p_S - (SimTK::dot(first.normal, p_S) - first.offset) * first.normal;
    // Tied normals may still cancel (the three sides of a triangular prism at its axis); the
    // first face's normal then.
    surface.n_S = sum.norm() > 1e-9 ? SimTK::UnitVec3(sum) : first.normal;
    return surface;
}

}  // namespace graspsim::contact
