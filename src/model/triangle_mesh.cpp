#include "graspsim/model/triangle_mesh.h"

#include "graspsim/error.h"

#include <libqhull_r/qhull_ra.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>

namespace graspsim::model {

namespace {

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 add(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec3 scale(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// Unit outward normal of triangle t (counter-clockwise seen from outside).
Vec3 findTriangleNormal(const TriangleMesh& mesh, const std::array<int, 3>& t) {
    const Vec3& a = mesh.vertices[t[0]];
    const Vec3 n = cross(sub(mesh.vertices[t[1]], a), sub(mesh.vertices[t[2]], a));
    const double length = std::sqrt(dot(n, n));
    return length > 0 ? scale(n, 1 / length) : Vec3{0, 0, 0};
}

// Closest point to P on triangle abc (Ericson, Real-Time Collision Detection, 5.1.5): which
// Voronoi region of the triangle P projects into decides vertex, edge or face.
Vec3 findClosestTrianglePoint(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 ab = sub(b, a), ac = sub(c, a), ap = sub(p, a);
    const double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return a;
    const Vec3 bp = sub(p, b);
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return add(a, scale(ab, d1 / (d1 - d3)));
    const Vec3 cp = sub(p, c);
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return add(a, scale(ac, d2 / (d2 - d6)));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
        return add(b, scale(sub(c, b), (d4 - d3) / ((d4 - d3) + (d5 - d6))));
    }
    const double denominator = 1 / (va + vb + vc);
    return add(a, add(scale(ab, vb * denominator), scale(ac, vc * denominator)));
}

// Signed distance of P from the plane of triangle t, positive on the outward side.
double calcPlaneDistance(const TriangleMesh& mesh, const std::array<int, 3>& t, const Vec3& p) {
    return dot(findTriangleNormal(mesh, t), sub(p, mesh.vertices[t[0]]));
}

}  // namespace

MassProperties calcMeshMassProperties(const TriangleMesh& mesh) {
    // Each triangle abc and the origin bound a tetrahedron of signed volume det[a b c]/6; its
    // second moment is det/120 (a a^T + b b^T + c c^T + s s^T) with s = a + b + c.
    double volume = 0;
    Vec3 firstMoment{0, 0, 0};
    double C[3][3] = {};
    for (const std::array<int, 3>& t : mesh.triangles) {
        const Vec3& a = mesh.vertices[t[0]];
        const Vec3& b = mesh.vertices[t[1]];
        const Vec3& c = mesh.vertices[t[2]];
        const double det = dot(a, cross(b, c));
        const Vec3 s = add(add(a, b), c);
        volume += det / 6;
        firstMoment = add(firstMoment, scale(s, det / 24));
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) C[j][k] += det / 120 * (a[j] * a[k] + b[j] * b[k] + c[j] * c[k] + s[j] * s[k]);
    }
    MassProperties mp;
    mp.mass = volume;
    if (volume == 0) return mp;
    mp.p_BCm = scale(firstMoment, 1 / volume);
    // Parallel-axis shift of the second moment to the centroid, then I = trace(C) 1 - C.
    for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k) C[j][k] -= volume * mp.p_BCm[j] * mp.p_BCm[k];
    mp.inertia.xx = C[1][1] + C[2][2];
    mp.inertia.yy = C[0][0] + C[2][2];
    mp.inertia.zz = C[0][0] + C[1][1];
    mp.inertia.xy = -C[0][1];
    mp.inertia.xz = -C[0][2];
    mp.inertia.yz = -C[1][2];
    return mp;
}

std::optional<std::pair<int, int>> findOpenEdge(const TriangleMesh& mesh) {
    std::map<std::pair<int, int>, int> edgeUses;
    for (const std::array<int, 3>& t : mesh.triangles) {
        for (int i = 0; i < 3; ++i) {
            const int u = t[i], v = t[(i + 1) % 3];
            ++edgeUses[{std::min(u, v), std::max(u, v)}];
        }
    }
    for (const auto& [edge, uses] : edgeUses) {
        if (uses != 2) return edge;
    }
    return std::nullopt;
}

double calcConvexHullVolume(const TriangleMesh& mesh, const std::string& source) {
    std::vector<double> points;
    for (const Vec3& v : mesh.vertices) points.insert(points.end(), v.begin(), v.end());
    // qhull reports through a FILE*; an in-memory stream keeps its messages off stderr.
    char* text = nullptr;
    std::size_t textSize = 0;
    std::FILE* errors = open_memstream(&text, &textSize);
    if (!errors) throw Error(source + ": cannot open a memory stream for qhull's messages");
    qhT qh;
    QHULL_LIB_CHECK
    qh_zero(&qh, errors);
    char command[] = "qhull Qt";
    const int exitCode = qh_new_qhull(&qh, 3, static_cast<int>(mesh.vertices.size()), points.data(), False, command,
                                      nullptr, errors);
    double volume = 0;
    if (exitCode == qh_ERRnone) {
        qh_getarea(&qh, qh.facet_list);
        volume = qh.totvol;
    }
    qh_freeqhull(&qh, !qh_ALL);
    int curlong = 0, totlong = 0;
    qh_memfreeshort(&qh, &curlong, &totlong);
    std::fclose(errors);
    std::free(text);
    if (exitCode != qh_ERRnone) {
        throw InputError(source + ": qhull cannot build the convex hull of its " +
                         std::to_string(mesh.vertices.size()) + " vertices (flat or degenerate); pass a solid mesh");
    }
    return volume;
}

double calcConvexMeshDistance(const TriangleMesh& mesh, const Vec3& p) {
    double planeDistance = -std::numeric_limits<double>::infinity();
    for (const std::array<int, 3>& t : mesh.triangles) planeDistance = std::max(planeDistance, calcPlaneDistance(mesh, t, p));
    // Inside a convex solid every face plane is behind P; the nearest one is the surface distance.
    if (planeDistance <= 0) return planeDistance;
    double nearest = std::numeric_limits<double>::infinity();
    for (const std::array<int, 3>& t : mesh.triangles) {
        const Vec3 q = findClosestTrianglePoint(p, mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
        nearest = std::min(nearest, std::sqrt(dot(sub(p, q), sub(p, q))));
    }
    return nearest;
}

Vec3 findConvexMeshNormal(const TriangleMesh& mesh, const Vec3& p) {
    double best = -std::numeric_limits<double>::infinity();
    Vec3 normal{0, 0, 1};
    for (const std::array<int, 3>& t : mesh.triangles) {
        const double d = calcPlaneDistance(mesh, t, p);
        if (d > best) {
            best = d;
            normal = findTriangleNormal(mesh, t);
        }
    }
    return normal;
}

}  // namespace graspsim::model
