#include "graspsim/model/geometry_inertia.h"

#include "graspsim/error.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace graspsim::model;

namespace {

Geometry capsule(double r, double L, const Transform& X = Transform::identity()) {
    Geometry g;
    g.type = Geometry::Type::Capsule;
    g.name = "c";
    g.radius = r;
    g.length = L;
    g.X_BG = X;
    return g;
}

Geometry box(const Vec3& half, const Transform& X = Transform::identity()) {
    Geometry g;
    g.type = Geometry::Type::Box;
    g.name = "b";
    g.halfLengths = half;
    g.X_BG = X;
    return g;
}

// Independent oracle: midpoint-rule integration of a capsule's volume and second moments on a grid.
void integrateCapsule(double r, double L, int n, double& volume, double& Ixx, double& Izz) {
    const double zMax = L / 2 + r;
    const double h = 2 * r / n, hz = 2 * zMax / (2 * n);
    volume = Ixx = Izz = 0;
    for (int i = 0; i < n; ++i) {
        const double x = -r + (i + 0.5) * h;
        for (int j = 0; j < n; ++j) {
            const double y = -r + (j + 0.5) * h;
            if (x * x + y * y > r * r) continue;
            for (int k = 0; k < 2 * n; ++k) {
                const double z = -zMax + (k + 0.5) * hz;
                const double dz = std::max(0.0, std::abs(z) - L / 2);
                if (x * x + y * y + dz * dz > r * r) continue;
                const double dV = h * h * hz;
                volume += dV;
                Ixx += (y * y + z * z) * dV;
                Izz += (x * x + y * y) * dV;
            }
        }
    }
}

}  // namespace

TEST(GeometryInertia, SphereMatchesClosedForm) {
    Geometry s;
    s.type = Geometry::Type::Sphere;
    s.radius = 0.05;
    const MassProperties mp = calcSolidMassProperties(s, 1000.0);
    const double m = 1000.0 * 4.0 / 3.0 * M_PI * std::pow(0.05, 3);
    EXPECT_NEAR(mp.mass, m, 1e-12);
    EXPECT_NEAR(mp.inertia.xx, 0.4 * m * 0.05 * 0.05, 1e-15);
    EXPECT_NEAR(mp.inertia.zz, mp.inertia.xx, 1e-15);
}

TEST(GeometryInertia, CapsuleOfZeroLengthIsASphere) {
    Geometry s;
    s.type = Geometry::Type::Sphere;
    s.radius = 0.01;
    const MassProperties sphere = calcSolidMassProperties(s, 1100.0);
    const MassProperties cap = calcSolidMassProperties(capsule(0.01, 0.0), 1100.0);
    EXPECT_NEAR(cap.mass, sphere.mass, 1e-15);
    EXPECT_NEAR(cap.inertia.xx, sphere.inertia.xx, 1e-18);
    EXPECT_NEAR(cap.inertia.zz, sphere.inertia.zz, 1e-18);
}

TEST(GeometryInertia, CapsuleMatchesGridIntegration) {
    const double r = 0.009, L = 0.03;
    double V = 0, Ixx = 0, Izz = 0;
    integrateCapsule(r, L, 120, V, Ixx, Izz);
    const MassProperties mp = calcSolidMassProperties(capsule(r, L), 1.0);
    EXPECT_NEAR(mp.mass / V, 1.0, 2e-3);
    EXPECT_NEAR(mp.inertia.xx / Ixx, 1.0, 3e-3);
    EXPECT_NEAR(mp.inertia.zz / Izz, 1.0, 3e-3);
}

TEST(GeometryInertia, TwoHalfBoxesMakeTheWholeBox) {
    const MassProperties whole = calcSolidMassProperties(box({0.1, 0.2, 0.3}), 500.0);
    const MassProperties halves = calcSolidMassProperties(
        std::vector<Geometry>{box({0.1, 0.1, 0.3}, Transform::translation({0, 0.1, 0})),
                              box({0.1, 0.1, 0.3}, Transform::translation({0, -0.1, 0}))},
        500.0);
    EXPECT_NEAR(halves.mass, whole.mass, 1e-12);
    EXPECT_NEAR(halves.inertia.xx, whole.inertia.xx, 1e-12);
    EXPECT_NEAR(halves.inertia.yy, whole.inertia.yy, 1e-12);
    EXPECT_NEAR(halves.inertia.zz, whole.inertia.zz, 1e-12);
    EXPECT_NEAR(halves.p_BCm[1], 0.0, 1e-15);
}

TEST(GeometryInertia, OffsetBodyGetsParallelAxisProducts) {
    // Two point-like equal spheres at (d, d, 0) and (-d, -d, 0): I_xy = -sum m x y = -2 m d^2.
    Geometry a;
    a.type = Geometry::Type::Sphere;
    a.radius = 1e-4;
    Geometry b = a;
    const double d = 0.1;
    a.X_BG = Transform::translation({d, d, 0});
    b.X_BG = Transform::translation({-d, -d, 0});
    const MassProperties mp = calcSolidMassProperties(std::vector<Geometry>{a, b}, 1.0);
    EXPECT_NEAR(mp.inertia.xy / (-mp.mass * d * d), 1.0, 1e-6);
}

TEST(GeometryInertia, RotatingABoxSwapsItsMoments) {
    const MassProperties straight = calcSolidMassProperties(box({0.1, 0.2, 0.3}), 1.0);
    const MassProperties turned =
        calcSolidMassProperties(box({0.1, 0.2, 0.3}, Transform::axisAngle({0, 0, 1}, M_PI / 2)), 1.0);
    EXPECT_NEAR(turned.inertia.xx, straight.inertia.yy, 1e-15);
    EXPECT_NEAR(turned.inertia.yy, straight.inertia.xx, 1e-15);
    EXPECT_NEAR(turned.inertia.xy, 0.0, 1e-15);
}

TEST(GeometryInertia, MeshHasNoVolume) {
    Geometry mesh;
    mesh.type = Geometry::Type::Mesh;
    mesh.meshFile = "hand.stl";
    EXPECT_THROW(calcVolume(mesh), graspsim::InputError);
}
