// Mass properties of closed meshes against closed forms: a box and a regular prism exactly, a
// fine sphere to its tessellation error; the topology, convexity and distance checks.
#include "graspsim/model/triangle_mesh.h"

#include "graspsim/error.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace graspsim::model;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Box [x0, x0 + a] x [y0, y0 + b] x [z0, z0 + c], triangles counter-clockwise from outside.
TriangleMesh makeBox(double a, double b, double c, const Vec3& corner) {
    TriangleMesh mesh;
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
            for (int k = 0; k < 2; ++k) mesh.vertices.push_back({corner[0] + i * a, corner[1] + j * b, corner[2] + k * c});
    const int quads[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
    for (const auto& q : quads) {
        mesh.triangles.push_back({q[0], q[1], q[2]});
        mesh.triangles.push_back({q[0], q[2], q[3]});
    }
    return mesh;
}

// A right prism over the regular n-gon of circumradius r, from z = -h/2 to h/2.
TriangleMesh makePrism(int n, double r, double h) {
    TriangleMesh mesh;
    for (int side = 0; side < 2; ++side)
        for (int i = 0; i < n; ++i)
            mesh.vertices.push_back({r * std::cos(2 * kPi * i / n), r * std::sin(2 * kPi * i / n), side ? h / 2 : -h / 2});
    const int bottom = 2 * n, top = 2 * n + 1;
    mesh.vertices.push_back({0, 0, -h / 2});
    mesh.vertices.push_back({0, 0, h / 2});
    for (int i = 0; i < n; ++i) {
        const int j = (i + 1) % n;
        mesh.triangles.push_back({i, j, j + n});
        mesh.triangles.push_back({i, j + n, i + n});
        mesh.triangles.push_back({bottom, j, i});
        mesh.triangles.push_back({top, i + n, j + n});
    }
    return mesh;
}

// A UV sphere of radius r with `rings` latitude bands and 2 * rings longitudes.
TriangleMesh makeSphere(int rings, double r) {
    TriangleMesh mesh;
    const int n = 2 * rings;
    mesh.vertices.push_back({0, 0, -r});
    for (int k = 1; k < rings; ++k) {
        const double theta = kPi * k / rings;
        for (int i = 0; i < n; ++i) {
            const double phi = 2 * kPi * i / n;
            mesh.vertices.push_back({r * std::sin(theta) * std::cos(phi), r * std::sin(theta) * std::sin(phi), -r * std::cos(theta)});
        }
    }
    mesh.vertices.push_back({0, 0, r});
    const int last = static_cast<int>(mesh.vertices.size()) - 1;
    auto ring = [n](int k, int i) { return 1 + (k - 1) * n + (i % n); };
    for (int i = 0; i < n; ++i) {
        mesh.triangles.push_back({0, ring(1, i + 1), ring(1, i)});
        mesh.triangles.push_back({last, ring(rings - 1, i), ring(rings - 1, i + 1)});
        for (int k = 1; k < rings - 1; ++k) {
            mesh.triangles.push_back({ring(k, i), ring(k, i + 1), ring(k + 1, i + 1)});
            mesh.triangles.push_back({ring(k, i), ring(k + 1, i + 1), ring(k + 1, i)});
        }
    }
    return mesh;
}

}  // namespace

TEST(TriangleMesh, BoxMassPropertiesAreExact) {
    const double a = 0.04, b = 0.06, c = 0.02;
    const Vec3 corner{0.3, -0.1, 0.05};
    const MassProperties mp = calcMeshMassProperties(makeBox(a, b, c, corner));
    const double V = a * b * c;
    EXPECT_NEAR(mp.mass, V, 1e-12 * V);
    EXPECT_NEAR(mp.p_BCm[0], corner[0] + a / 2, 1e-12);
    EXPECT_NEAR(mp.p_BCm[1], corner[1] + b / 2, 1e-12);
    EXPECT_NEAR(mp.p_BCm[2], corner[2] + c / 2, 1e-12);
    const double scale = V * (a * a + b * b) / 12;
    EXPECT_NEAR(mp.inertia.xx, V * (b * b + c * c) / 12, 1e-12 * scale);
    EXPECT_NEAR(mp.inertia.yy, V * (a * a + c * c) / 12, 1e-12 * scale);
    EXPECT_NEAR(mp.inertia.zz, V * (a * a + b * b) / 12, 1e-12 * scale);
    EXPECT_NEAR(mp.inertia.xy, 0, 1e-12 * scale);
    EXPECT_NEAR(mp.inertia.xz, 0, 1e-12 * scale);
    EXPECT_NEAR(mp.inertia.yz, 0, 1e-12 * scale);
}

TEST(TriangleMesh, RegularPrismMatchesThePolygonClosedFormAndApproachesTheCylinder) {
    const int n = 256;
    const double r = 0.03, h = 0.1, s = std::sin(2 * kPi / n), c = std::cos(2 * kPi / n);
    const MassProperties mp = calcMeshMassProperties(makePrism(n, r, h));
    // Regular n-gon of circumradius r: area n r^2 sin(2 pi/n)/2, polar moment n r^4 sin (2 + cos)/12.
    const double area = n * r * r * s / 2, polar = n * r * r * r * r * s * (2 + c) / 12;
    const double V = area * h;
    EXPECT_NEAR(mp.mass, V, 1e-12 * V);
    EXPECT_NEAR(mp.inertia.zz, polar * h, 1e-12 * polar * h);
    EXPECT_NEAR(mp.inertia.xx, polar * h / 2 + V * h * h / 12, 1e-12 * polar * h);
    EXPECT_NEAR(mp.inertia.xy, 0, 1e-12 * polar * h);
    // ... and the cylinder, to the polygon's area deficit (about (2 pi/n)^2/6 = 1e-4).
    const double cylinder = kPi * r * r * h;
    EXPECT_NEAR(mp.mass, cylinder, 2e-4 * cylinder);
    EXPECT_NEAR(mp.inertia.zz, cylinder * r * r / 2, 4e-4 * cylinder * r * r / 2);
}

TEST(TriangleMesh, FineSphereApproachesTheSphereClosedForm) {
    const double r = 0.045;
    const MassProperties mp = calcMeshMassProperties(makeSphere(128, r));
    const double V = 4.0 / 3.0 * kPi * r * r * r, I = 0.4 * V * r * r;
    // An inscribed polyhedron of 128 bands and 256 longitudes lies inside the sphere and misses a
    // fraction of order (pi/128)^2 of its volume: 1e-3 bounds it.
    EXPECT_LT(mp.mass, V);
    EXPECT_NEAR(mp.mass, V, 1e-3 * V);
    EXPECT_NEAR(mp.inertia.xx, I, 2e-3 * I);
    EXPECT_NEAR(mp.inertia.yy, I, 2e-3 * I);
    EXPECT_NEAR(mp.inertia.zz, I, 2e-3 * I);
    EXPECT_NEAR(std::hypot(mp.p_BCm[0], mp.p_BCm[1], mp.p_BCm[2]), 0, 1e-12);
}

TEST(TriangleMesh, ProductsOfInertiaAreKeptForATiltedBox) {
    // A box whose edges are turned 30 deg about z off the mesh axes: the mesh's axes are kept,
    // so the inertia must carry the products R diag(Ix, Iy, Iz) R^T gives.
    TriangleMesh box = makeBox(0.04, 0.02, 0.01, {-0.02, -0.01, -0.005});
    const double t = kPi / 6, ct = std::cos(t), st = std::sin(t);
    for (Vec3& v : box.vertices) v = {ct * v[0] - st * v[1], st * v[0] + ct * v[1], v[2]};
    const MassProperties mp = calcMeshMassProperties(box);
    const double V = 0.04 * 0.02 * 0.01, Ix = V * (0.02 * 0.02 + 0.01 * 0.01) / 12, Iy = V * (0.04 * 0.04 + 0.01 * 0.01) / 12;
    // I_rot = R diag(Ix, Iy, Iz) R^T: xy entry (Ix - Iy) cos sin.
    EXPECT_NEAR(mp.inertia.xy, (Ix - Iy) * ct * st, 1e-12 * Iy);
    EXPECT_NEAR(mp.inertia.xx, Ix * ct * ct + Iy * st * st, 1e-12 * Iy);
}

TEST(TriangleMesh, InvertedTrianglesGiveNegativeVolume) {
    TriangleMesh box = makeBox(0.01, 0.02, 0.03, {0, 0, 0});
    for (auto& t : box.triangles) std::swap(t[1], t[2]);
    EXPECT_NEAR(calcMeshMassProperties(box).mass, -6e-6, 1e-18);
}

TEST(TriangleMesh, OpenEdgeIsFound) {
    TriangleMesh box = makeBox(0.01, 0.02, 0.03, {0, 0, 0});
    EXPECT_FALSE(findOpenEdge(box).has_value());
    box.triangles.pop_back();
    EXPECT_TRUE(findOpenEdge(box).has_value());
}

TEST(TriangleMesh, HullVolumeOfAConvexMeshIsItsVolume) {
    const TriangleMesh prism = makePrism(32, 0.02, 0.05);
    EXPECT_NEAR(calcConvexHullVolume(prism, "test"), calcMeshMassProperties(prism).mass, 1e-12);
}

TEST(TriangleMesh, FlatVerticesAreRefused) {
    TriangleMesh flat;
    flat.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    flat.triangles = {{0, 1, 2}, {1, 3, 2}};
    EXPECT_THROW(calcConvexHullVolume(flat, "test"), graspsim::InputError);
}

TEST(TriangleMesh, ConvexDistanceMatchesTheBoxClosedForm) {
    const TriangleMesh box = makeBox(0.04, 0.06, 0.02, {-0.02, -0.03, -0.01});
    EXPECT_NEAR(calcConvexMeshDistance(box, {0, 0, 0}), -0.01, 1e-15);        // nearest face: z
    EXPECT_NEAR(calcConvexMeshDistance(box, {0.03, 0, 0}), 0.01, 1e-15);      // in front of +x
    EXPECT_NEAR(calcConvexMeshDistance(box, {0.03, 0.04, 0}), std::sqrt(2e-4), 1e-15);  // off an edge
    EXPECT_NEAR(calcConvexMeshDistance(box, {0.03, 0.04, 0.02}), std::sqrt(3e-4), 1e-15);  // off a corner
    const Vec3 n = findConvexMeshNormal(box, {0.019, 0, 0});
    EXPECT_NEAR(n[0], 1, 1e-15);
}
