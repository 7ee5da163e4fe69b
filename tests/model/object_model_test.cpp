#include "graspsim/model/object_model.h"

#include "graspsim/error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace graspsim::model;

TEST(ObjectModel, BallIsAUniformSphereOfTheThesisMass) {
    const ModelDescription ball = buildBallModel();
    const Body& b = ball.bodies.at(0);
    EXPECT_DOUBLE_EQ(b.mass, 0.200);
    EXPECT_NEAR(b.inertia.xx, 0.4 * 0.200 * kBallRadius * kBallRadius, 1e-15);
    EXPECT_EQ(b.geometry.at(0).type, Geometry::Type::Sphere);
}

TEST(ObjectModel, PhoneIsAUniformBoxOfTheThesisMassAndSize) {
    const ModelDescription phone = buildPhoneModel();
    const Body& b = phone.bodies.at(0);
    EXPECT_DOUBLE_EQ(b.mass, 0.100);
    const double w = 0.07, l = 0.14, t = 0.008;
    EXPECT_NEAR(b.inertia.xx, 0.1 * (l * l + t * t) / 12, 1e-15);
    EXPECT_NEAR(b.inertia.yy, 0.1 * (w * w + t * t) / 12, 1e-15);
    EXPECT_NEAR(b.inertia.zz, 0.1 * (w * w + l * l) / 12, 1e-15);
}

TEST(ObjectModel, UnknownObjectIsNamed) {
    try {
        buildObjectModel("cube", "object name");
        FAIL();
    } catch (const graspsim::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("'cube'"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("ball or phone"), std::string::npos);
    }
}

namespace {

constexpr double kPi = 3.14159265358979323846;

// Composite Simpson integration of f over [a, b] with n (even) intervals.
template <class F>
double integrate(F f, double a, double b, int n) {
    const double h = (b - a) / n;
    double sum = f(a) + f(b);
    for (int i = 1; i < n; ++i) sum += f(a + i * h) * (i % 2 ? 4 : 2);
    return sum * h / 3;
}

}  // namespace

TEST(ObjectModel, CylinderHasTheClosedFormInertia) {
    const double m = 0.3, r = 0.02, L = 0.12;
    const ModelDescription model = buildCylinderModel(m, r, L);
    const Body& b = model.bodies.at(0);
    EXPECT_EQ(b.name, "cylinder");
    EXPECT_DOUBLE_EQ(b.mass, m);
    EXPECT_NEAR(b.inertia.xx, m * (3 * r * r + L * L) / 12, 1e-15);
    EXPECT_NEAR(b.inertia.yy, m * (3 * r * r + L * L) / 12, 1e-15);
    EXPECT_NEAR(b.inertia.zz, m * r * r / 2, 1e-15);
}

TEST(ObjectModel, CapsuleMatchesSlicesIntegratedAlongItsAxis) {
    // Second, independent method: thin discs of radius rho(z) stacked along z, each with
    // dI_zz = rho^4 pi/2 dz and dI_xx = pi rho^2 (rho^2/4 + z^2) dz (unit density).
    const double m = 0.25, r = 0.015, L = 0.08;
    auto rho2 = [&](double z) {
        const double beyond = std::max(0.0, std::abs(z) - L / 2);
        return std::max(0.0, r * r - beyond * beyond);
    };
    const double half = L / 2 + r;
    const int n = 20000;
    const double V = integrate([&](double z) { return kPi * rho2(z); }, -half, half, n);
    const double Izz = integrate([&](double z) { return kPi / 2 * rho2(z) * rho2(z); }, -half, half, n);
    const double Ixx = integrate([&](double z) { return kPi * rho2(z) * (rho2(z) / 4 + z * z); }, -half, half, n);
    const ModelDescription model = buildCapsuleModel(m, r, L);
    const Body& b = model.bodies.at(0);
    EXPECT_EQ(b.geometry.at(0).type, Geometry::Type::Capsule);
    EXPECT_NEAR(b.inertia.zz, m * Izz / V, 1e-6 * b.inertia.zz);
    EXPECT_NEAR(b.inertia.xx, m * Ixx / V, 1e-6 * b.inertia.xx);
    EXPECT_NEAR(b.inertia.yy, b.inertia.xx, 1e-18);
}

TEST(ObjectModel, EllipsoidHasTheClosedFormInertia) {
    const double m = 0.15, a = 0.03, bb = 0.02, c = 0.05;
    const ModelDescription model = buildEllipsoidModel(m, {a, bb, c});
    const Body& b = model.bodies.at(0);
    EXPECT_EQ(b.geometry.at(0).type, Geometry::Type::Ellipsoid);
    EXPECT_NEAR(b.inertia.xx, m * (bb * bb + c * c) / 5, 1e-15);
    EXPECT_NEAR(b.inertia.yy, m * (a * a + c * c) / 5, 1e-15);
    EXPECT_NEAR(b.inertia.zz, m * (a * a + bb * bb) / 5, 1e-15);
}

TEST(ObjectModel, MeshIsMovedToItsCentroidAndHasTheBoxInertia) {
    // A box 0.04 x 0.06 x 0.02 m with a corner at the origin: the builder centres it.
    TriangleMesh box;
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
            for (int k = 0; k < 2; ++k) box.vertices.push_back({0.04 * i, 0.06 * j, 0.02 * k});
    const int quads[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
    for (const auto& q : quads) {
        box.triangles.push_back({q[0], q[1], q[2]});
        box.triangles.push_back({q[0], q[2], q[3]});
    }
    const double m = 0.1;
    const ModelDescription model = buildMeshModel(m, box, "box.stl", {1, 1, 1});
    const Body& b = model.bodies.at(0);
    EXPECT_EQ(b.name, "mesh");
    EXPECT_EQ(b.geometry.at(0).meshFile, "box.stl");
    for (double c : b.p_BCm) EXPECT_NEAR(c, 0, 1e-15);
    const Vec3 p_OG = b.geometry.at(0).X_BG.p;
    EXPECT_NEAR(p_OG[0], -0.02, 1e-15);
    EXPECT_NEAR(p_OG[1], -0.03, 1e-15);
    EXPECT_NEAR(p_OG[2], -0.01, 1e-15);
    EXPECT_NEAR(b.inertia.xx, m * (0.06 * 0.06 + 0.02 * 0.02) / 12, 1e-12 * b.inertia.xx);
    EXPECT_NEAR(b.inertia.zz, m * (0.04 * 0.04 + 0.06 * 0.06) / 12, 1e-12 * b.inertia.zz);
    EXPECT_NEAR(b.inertia.xy, 0, 1e-18);
}
