#include "graspsim/contact/surface_point.h"

#include <gtest/gtest.h>

#include <random>

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

}  // namespace
}  // namespace graspsim::contact
