#include "graspsim/contact/surface_point.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "test_meshes.h"

namespace graspsim::contact {
namespace {

// Oracle: the reported point lies on the surface (signed distance 0 by the shape's own
// inequality), |Q - P| equals |distance|, and Q - P is along the normal with the distance's sign.
void expectConsistent(const ContactShape& shape, const SimTK::Vec3& p_SQ) {
    const SurfacePoint s = findSurfacePoint(shape, p_SQ);
    const SimTK::Vec3 r_PQ = p_SQ - s.p_SP;
    EXPECT_NEAR(r_PQ.norm(), std::abs(s.distance), 1e-12);
    if (std::abs(s.distance) > 1e-9) {
        EXPECT_NEAR(dot(r_PQ, SimTK::Vec3(s.n_S)), s.distance, 1e-12);
    }
    const SurfacePoint again = findSurfacePoint(shape, s.p_SP);
    EXPECT_NEAR(again.distance, 0, 1e-12);
}

TEST(SurfacePoint, SphereDistanceIsCentreDistanceMinusRadius) {
    const ContactShape ball = ContactShape::sphere(0.045);
    const SurfacePoint s = findSurfacePoint(ball, SimTK::Vec3(0, 0.05, 0));
    EXPECT_NEAR(s.distance, 0.005, 1e-15);
    EXPECT_NEAR(s.p_SP[1], 0.045, 1e-15);
    EXPECT_NEAR(s.n_S[1], 1, 1e-15);
    EXPECT_NEAR(findSurfacePoint(ball, SimTK::Vec3(0)).distance, -0.045, 1e-15);
}

TEST(SurfacePoint, CapsuleUsesTheClosestPointOfItsAxis) {
    const ContactShape capsule = ContactShape::capsule(0.01, 0.04);
    EXPECT_NEAR(findSurfacePoint(capsule, SimTK::Vec3(0.03, 0, 0.01)).distance, 0.02, 1e-15);
    EXPECT_NEAR(findSurfacePoint(capsule, SimTK::Vec3(0, 0, 0.05)).distance, 0.02, 1e-15);
}

TEST(SurfacePoint, BoxInsideTakesTheNearestFace) {
    const ContactShape box = ContactShape::box(SimTK::Vec3(0.035, 0.07, 0.004));
    const SurfacePoint s = findSurfacePoint(box, SimTK::Vec3(0.01, 0.02, -0.001));
    EXPECT_NEAR(s.distance, -0.003, 1e-15);
    EXPECT_NEAR(s.n_S[2], -1, 1e-15);
    EXPECT_NEAR(s.p_SP[2], -0.004, 1e-15);
}

TEST(SurfacePoint, RandomPointsAreConsistentForEveryShape) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coordinate(-0.08, 0.08);
    const ContactShape shapes[] = {ContactShape::sphere(0.045), ContactShape::capsule(0.02, 0.06),
                                   ContactShape::box(SimTK::Vec3(0.035, 0.07, 0.004)),
                                   ContactShape::halfSpace()};
    for (const ContactShape& shape : shapes) {
        for (int i = 0; i < 200; ++i) {
            expectConsistent(shape, SimTK::Vec3(coordinate(random), coordinate(random), coordinate(random)));
        }
    }
}

TEST(SurfacePoint, RandomPointsAreConsistentForTheObjectShapes) {
    std::mt19937 random(9);
    std::uniform_real_distribution<double> coordinate(-0.08, 0.08);
    const ContactShape shapes[] = {
        ContactShape::cylinder(0.03, 0.1),
        ContactShape::ellipsoid(SimTK::Vec3(0.04, 0.03, 0.02)),
        ContactShape::ellipsoid(SimTK::Vec3(0.03, 0.05, 0.03)),  // a spheroid: equal axes
        ContactShape::ellipsoid(SimTK::Vec3(0.03, 0.03, 0.03)),  // a sphere
        ContactShape::ellipsoid(SimTK::Vec3(0.06, 0.05, 0.002)),  // a thin lens
        ContactShape::ellipsoid(SimTK::Vec3(0.002, 0.003, 0.07)),  // a needle
        test::makeMeshShape(test::makeBoxMesh(SimTK::Vec3(0.035, 0.07, 0.004))),
        test::makeMeshShape(test::makeCylinderMesh(0.03, 0.1, 24))};
    for (const ContactShape& shape : shapes) {
        for (int i = 0; i < 300; ++i) {
            expectConsistent(shape, SimTK::Vec3(coordinate(random), coordinate(random), coordinate(random)));
        }
        // Points on the coordinate planes and axes, where the ellipsoid's solution changes case.
        for (int i = 0; i < 60; ++i) {
            SimTK::Vec3 p(coordinate(random), coordinate(random), coordinate(random));
            p[i % 3] = 0;
            if (i % 2) p[(i + 1) % 3] = 0;
            expectConsistent(shape, p);
        }
    }
}

TEST(SurfacePoint, CylinderSideCapAndRim) {
    const ContactShape cylinder = ContactShape::cylinder(0.03, 0.1);
    const SurfacePoint side = findSurfacePoint(cylinder, SimTK::Vec3(0.03, 0.04, 0.01));
    EXPECT_NEAR(side.distance, 0.02, 1e-15);
    EXPECT_NEAR(side.n_S[0], 0.6, 1e-15);
    const SurfacePoint cap = findSurfacePoint(cylinder, SimTK::Vec3(0.01, 0, -0.045));
    EXPECT_NEAR(cap.distance, -0.005, 1e-15);
    EXPECT_NEAR(cap.n_S[2], -1, 1e-15);
    const SurfacePoint rim = findSurfacePoint(cylinder, SimTK::Vec3(0.034, 0, 0.053));
    EXPECT_NEAR(rim.distance, 0.005, 1e-15);
    EXPECT_NEAR((rim.p_SP - SimTK::Vec3(0.03, 0, 0.05)).norm(), 0, 1e-15);
}

// Oracle: brute force over the ellipsoid's surface: a 300 x 600 grid of parametric angles,
// then twice a 201 x 201 grid over the 4 x 4 cells around the best sample. The sampled distance bounds
// the exact one from above and exceeds it only by the refined sampling's small error.
SimTK::Vec3 findEllipsoidPoint(const SimTK::Vec3& e, double u, double v) {
    return SimTK::Vec3(e[0] * std::cos(v) * std::cos(u), e[1] * std::cos(v) * std::sin(u), e[2] * std::sin(v));
}

double findSampledDistance(const SimTK::Vec3& e, const SimTK::Vec3& q) {
    double best = SimTK::Infinity, bestU = 0, bestV = 0;
    const auto sample = [&](int rows, int columns, double u0, double du, double v0, double dv) {
        for (int i = 0; i <= rows; ++i) {
            for (int j = 0; j <= columns; ++j) {
                const double u = u0 + du * j, v = v0 + dv * i;
                const double d = (q - findEllipsoidPoint(e, u, v)).norm();
                if (d < best) best = d, bestU = u, bestV = v;
            }
        }
    };
    const double du = 2 * SimTK::Pi / 600, dv = SimTK::Pi / 300;
    sample(300, 600, 0, du, -SimTK::Pi / 2, dv);
    sample(200, 200, bestU - 2 * du, du / 50, bestV - 2 * dv, dv / 50);
    sample(200, 200, bestU - 2 * du / 50, du / 2500, bestV - 2 * dv / 50, dv / 2500);
    return best;
}

TEST(SurfacePoint, EllipsoidAgainstBruteForceSampling) {
    const SimTK::Vec3 e(0.04, 0.03, 0.015);
    const ContactShape ellipsoid = ContactShape::ellipsoid(e);
    std::mt19937 random(4);
    std::uniform_real_distribution<double> coordinate(-0.06, 0.06);
    for (int k = 0; k < 16; ++k) {
        const double scale = k < 8 ? 1 : 0.3;  // half the points inside
        const SimTK::Vec3 q = scale * SimTK::Vec3(coordinate(random), coordinate(random), coordinate(random));
        const double sampled = findSampledDistance(e, q);
        const SurfacePoint exact = findSurfacePoint(ellipsoid, q);
        EXPECT_LE(std::abs(exact.distance), sampled + 1e-12) << q;
        EXPECT_LE(sampled - std::abs(exact.distance), 1e-9) << q;
        const bool inside = std::pow(q[0] / e[0], 2) + std::pow(q[1] / e[1], 2) + std::pow(q[2] / e[2], 2) < 1;
        EXPECT_EQ(exact.distance < 0, inside) << q;
    }
}

}  // namespace
}  // namespace graspsim::contact
