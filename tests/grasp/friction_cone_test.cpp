#include "graspsim/grasp/friction_cone.h"

#include "graspsim/error.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>

using namespace graspsim;
using grasp::FrictionCone;

namespace {

const Eigen::Vector3d n = Eigen::Vector3d(1, -2, 0.5).normalized();
const Eigen::Vector3d t1 = grasp::findTangent(n);
const Eigen::Vector3d t2 = n.cross(t1);

Eigen::Matrix3d secondMoment(const Eigen::Matrix3Xd& basis) { return basis * basis.transpose(); }

}  // namespace

TEST(FindTangent, IsAUnitVectorPerpendicularToTheNormal) {
    for (const Eigen::Vector3d& v :
         {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, -1, 0), Eigen::Vector3d(0, 0, 1),
          Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(-3, 0.001, 2)}) {
        const Eigen::Vector3d u = v.normalized();
        const Eigen::Vector3d t = grasp::findTangent(u);
        EXPECT_NEAR(t.norm(), 1, 1e-15);
        EXPECT_NEAR(t.dot(u), 0, 1e-15);
    }
}

// Box: |f.t1| = |f.t2| = mu f.n at each edge, one edge per corner of the square section.
TEST(FrictionConeBasis, BoxEdgesAreTheCornersOfTheBox) {
    const double mu = 0.4;
    const Eigen::Matrix3Xd f = grasp::calcFrictionConeBasis(n, t1, mu, FrictionCone::Box);
    ASSERT_EQ(f.cols(), 4);
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    for (int j = 0; j < 4; ++j) {
        EXPECT_NEAR(f.col(j).dot(n), 1, 1e-15);
        EXPECT_NEAR(std::abs(f.col(j).dot(t1)), mu, 1e-15);
        EXPECT_NEAR(std::abs(f.col(j).dot(t2)), mu, 1e-15);
        sum += Eigen::Vector2d(f.col(j).dot(t1), f.col(j).dot(t2));
    }
    EXPECT_NEAR(sum.norm(), 0, 1e-15);  // all four corners, not a repeated one
    EXPECT_NEAR((f.col(0) - (n + mu * t1 + mu * t2)).norm(), 0, 1e-15);
}

// Polyhedral: every edge lies on the exact cone, |f_t| = mu f.n.
TEST(FrictionConeBasis, PolyhedralEdgesLieOnTheExactCone) {
    const double mu = 0.7;
    const Eigen::Matrix3Xd f = grasp::calcFrictionConeBasis(n, t1, mu, FrictionCone::Polyhedral, 7);
    ASSERT_EQ(f.cols(), 7);
    for (int j = 0; j < 7; ++j) {
        EXPECT_NEAR(f.col(j).dot(n), 1, 1e-15);
        EXPECT_NEAR((f.col(j) - n).norm(), mu, 1e-15);
    }
}

TEST(FrictionConeBasis, FourEdgedPolyhedralConeIsNormalPlusMinusMuTangents) {
    const double mu = 0.3;
    const Eigen::Matrix3Xd f = grasp::calcFrictionConeBasis(n, t1, mu, FrictionCone::Polyhedral, 4);
    EXPECT_NEAR((f.col(0) - (n + mu * t1)).norm(), 0, 1e-15);
    EXPECT_NEAR((f.col(1) - (n + mu * t2)).norm(), 0, 1e-15);
    EXPECT_NEAR((f.col(2) - (n - mu * t1)).norm(), 0, 1e-15);
    EXPECT_NEAR((f.col(3) - (n - mu * t2)).norm(), 0, 1e-15);
}

// The lemma behind every hand-computed sigma_min in grasp_quality_test (see example_grasps.h).
TEST(FrictionConeBasis, SecondMomentIsIndependentOfTheTangentBasis) {
    const double mu = 0.6;
    const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - n * n.transpose();
    const Eigen::Vector3d t1Rotated = std::cos(1.1) * t1 + std::sin(1.1) * t2;
    for (const Eigen::Vector3d& t : {t1, t1Rotated}) {
        const Eigen::Matrix3d box =
            secondMoment(grasp::calcFrictionConeBasis(n, t, mu, FrictionCone::Box));
        EXPECT_NEAR((box - (4 * n * n.transpose() + 4 * mu * mu * P)).norm(), 0, 1e-14);
        for (int k : {3, 4, 5, 8}) {
            const Eigen::Matrix3d poly =
                secondMoment(grasp::calcFrictionConeBasis(n, t, mu, FrictionCone::Polyhedral, k));
            EXPECT_NEAR((poly - (k * n * n.transpose() + k * mu * mu / 2 * P)).norm(), 0, 1e-14)
                << "k = " << k;
        }
    }
}

TEST(FrictionConeBasis, FrictionlessContactPushesAlongTheNormalOnly) {
    const Eigen::Matrix3Xd f = grasp::calcFrictionConeBasis(n, t1, 0, FrictionCone::Box);
    for (int j = 0; j < 4; ++j) EXPECT_NEAR((f.col(j) - n).norm(), 0, 1e-15);
}

TEST(FrictionConeBasis, RejectsBadParametersNamingTheValue) {
    try {
        grasp::calcFrictionConeBasis(n, t1, -0.5, FrictionCone::Box);
        FAIL() << "negative mu accepted";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(),
                     "grasp quality: friction coefficient mu (-0.5) must be finite and >= 0");
    }
    EXPECT_THROW(grasp::calcFrictionConeBasis(n, t1, std::nan(""), FrictionCone::Box), InputError);
    try {
        grasp::calcFrictionConeBasis(n, t1, 0.5, FrictionCone::Polyhedral, 2);
        FAIL() << "2-edge cone accepted";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(),
                     "grasp quality: a polyhedral friction cone needs edges >= 3 (got 2)");
    }
    // The box ignores `edges`.
    EXPECT_EQ(grasp::calcFrictionConeBasis(n, t1, 0.5, FrictionCone::Box, 0).cols(), 4);
}
