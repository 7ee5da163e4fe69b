// The per-axis law and rotation-vector chart of LimitedBushing against closed forms.
#include "graspsim/grasp/limited_bushing_law.h"

#include <gtest/gtest.h>

#include <cmath>

namespace graspsim::grasp {
namespace {

constexpr double kStiffness = 1000;  // N/m
constexpr double kLimit = 2;         // N; elastic range L/K = 2 mm
constexpr double kWidth = 0.01;

TEST(LimitedBushingLaw, SticksBelowTheOnsetBand) {
    EXPECT_EQ(calcSlipFraction(kStiffness, kLimit, kWidth, 0.98 * kLimit / kStiffness, 1.0), 0);
    EXPECT_EQ(calcSlipFraction(kStiffness, kLimit, kWidth, -1.5e-3, -3.0), 0);
}

TEST(LimitedBushingLaw, SlidesFullyAtTheLimitWhileLoading) {
    EXPECT_EQ(calcSlipFraction(kStiffness, kLimit, kWidth, kLimit / kStiffness, 0.1), 1);
    EXPECT_EQ(calcSlipFraction(kStiffness, kLimit, kWidth, -kLimit / kStiffness, -0.1), 1);
}

// Past the limit the anchor outruns the motion, g = 1 + ((u - 1) / w)^2, so |K e| returns to L.
TEST(LimitedBushingLaw, PullsBackToTheLimitWhenPastIt) {
    const double u = 1 + 0.5 * kWidth;
    EXPECT_NEAR(calcSlipFraction(kStiffness, kLimit, kWidth, -u * kLimit / kStiffness, -0.1), 1.25,
                1e-9);
}

TEST(LimitedBushingLaw, SmoothstepInsideTheBand) {
    const double eMid = (1 - kWidth / 2) * kLimit / kStiffness;
    EXPECT_NEAR(calcSlipFraction(kStiffness, kLimit, kWidth, eMid, 0.1), 0.5, 1e-9);
    const double eQuarter = (1 - 0.75 * kWidth) * kLimit / kStiffness;  // t = 1/4
    EXPECT_NEAR(calcSlipFraction(kStiffness, kLimit, kWidth, eQuarter, 0.1),
                3.0 / 16 - 2.0 / 64, 1e-9);
}

TEST(LimitedBushingLaw, UnloadingAndRestStick) {
    const double e = 1.5 * kLimit / kStiffness;
    EXPECT_EQ(calcSlipFraction(kStiffness, kLimit, kWidth, e, -0.1), 0);
    EXPECT_EQ(calcSlipFraction(kStiffness, kLimit, kWidth, e, 0.0), 0);
}

TEST(LimitedBushingLaw, LockedAndZeroLimits) {
    EXPECT_EQ(calcSlipFraction(kStiffness, SimTK::Infinity, kWidth, 1.0, 1.0), 0);
    EXPECT_EQ(calcSlipFraction(kStiffness, 0, kWidth, 1e-9, 1.0), 1);
    EXPECT_EQ(calcSlipFraction(kStiffness, 0, kWidth, 0, 1.0), 0);
}

TEST(LimitedBushingLaw, ForceIsSpringDamperClampedAtTheLimit) {
    EXPECT_DOUBLE_EQ(calcAxisForce(kStiffness, 10, kLimit, 1e-3, 0.05), -1.0 - 0.5);
    EXPECT_DOUBLE_EQ(calcAxisForce(kStiffness, 10, kLimit, 5e-3, 0), -kLimit);
    EXPECT_DOUBLE_EQ(calcAxisForce(kStiffness, 10, kLimit, -1e-3, -1), kLimit);
    EXPECT_DOUBLE_EQ(calcAxisForce(kStiffness, 10, SimTK::Infinity, 1.0, 0), -kStiffness);
    EXPECT_DOUBLE_EQ(calcAxisForce(kStiffness, 10, 0, 1.0, 1.0), 0);
}

// Two-sided limits [-L-, +L+]: the elastic force -K e is positive for e < 0, so that side slips at
// L+ = 3 N and the other at L- = 1 N; the force clamps at each side's own limit.
TEST(LimitedBushingLaw, TwoSidedSlipsAtTheLoadedSidesLimit) {
    const double lower = 1, upper = 3;
    EXPECT_EQ(findLoadedSideLimit(lower, upper, -1e-3), upper);
    EXPECT_EQ(findLoadedSideLimit(lower, upper, 1e-3), lower);
    // K |e| = 2 N: past L- = 1 N on the positive side (slides), inside L+ = 3 N on the negative one.
    EXPECT_GT(calcTwoSidedSlipFraction(kStiffness, lower, upper, kWidth, 2e-3, 0.1), 1);
    EXPECT_EQ(calcTwoSidedSlipFraction(kStiffness, lower, upper, kWidth, -2e-3, -0.1), 0);
    // Exactly at each side's limit: full slip.
    EXPECT_EQ(calcTwoSidedSlipFraction(kStiffness, lower, upper, kWidth, lower / kStiffness, 0.1), 1);
    EXPECT_EQ(calcTwoSidedSlipFraction(kStiffness, lower, upper, kWidth, -upper / kStiffness, -0.1), 1);
    // Onset band of the upper side: half way through it, s = 1/2.
    EXPECT_NEAR(calcTwoSidedSlipFraction(kStiffness, lower, upper, kWidth, -(1 - kWidth / 2) * upper / kStiffness, -0.1),
                0.5, 1e-9);
    EXPECT_DOUBLE_EQ(calcTwoSidedAxisForce(kStiffness, 10, lower, upper, 5e-3, 0), -lower);
    EXPECT_DOUBLE_EQ(calcTwoSidedAxisForce(kStiffness, 10, lower, upper, -5e-3, 0), upper);
    EXPECT_DOUBLE_EQ(calcTwoSidedAxisForce(kStiffness, 10, lower, upper, -2e-3, 0), 2);  // elastic
    EXPECT_DOUBLE_EQ(calcTwoSidedAxisForce(kStiffness, 10, lower, SimTK::Infinity, -1.0, 0), kStiffness);
}

// Equal sides are the symmetric law, bit for bit (the thesis runs must not change).
TEST(LimitedBushingLaw, TwoSidedWithEqualSidesIsTheSymmetricLaw) {
    for (double limit : {0.0, 0.7, kLimit, SimTK::Infinity}) {
        for (double e : {-3e-3, -1.99e-3, -1e-4, 0.0, 1e-4, 1.985e-3, 2.01e-3}) {
            for (double r : {-0.2, 0.0, 0.3}) {
                EXPECT_EQ(calcTwoSidedSlipFraction(kStiffness, limit, limit, kWidth, e, r),
                          calcSlipFraction(kStiffness, limit, kWidth, e, r));
                EXPECT_EQ(calcTwoSidedAxisForce(kStiffness, 10, limit, limit, e, r), calcAxisForce(kStiffness, 10, limit, e, r));
            }
        }
    }
    const SimTK::Vec6 lower(1, 2, 3, 4, 5, 6), upper(6, 5, 4, 3, 2, 1);
    EXPECT_EQ(findLargerSide(lower, upper), SimTK::Vec6(6, 5, 4, 4, 5, 6));
    EXPECT_EQ(findLargerSide(lower, lower), lower);
    EXPECT_EQ(applyAxisLocks(lower, {true, false, false, false, false, true}), SimTK::Vec6(SimTK::Infinity, 2, 3, 4, 5, SimTK::Infinity));
}

TEST(LimitedBushingLaw, RotationVectorRoundTrip) {
    for (const SimTK::Vec3& theta :
         {SimTK::Vec3(0.3, -0.2, 0.9), SimTK::Vec3(1e-7, 0, -2e-7), SimTK::Vec3(0, 3.0, 0)}) {
        const SimTK::Vec3 back = calcRotationVector(calcRotationFromVector(theta));
        EXPECT_LT((back - theta).norm(), 1e-12) << theta;
    }
    EXPECT_EQ(calcRotationVector(calcRotationFromVector(SimTK::Vec3(0))).norm(), 0);
    // A right-handed turn of 0.7 rad about z: x goes to (cos, sin, 0).
    const SimTK::Mat33 R = calcRotationFromVector(SimTK::Vec3(0, 0, 0.7)).asMat33();  // a copy: the rotation is a temporary
    EXPECT_NEAR(R(0, 0), std::cos(0.7), 1e-15);
    EXPECT_NEAR(R(1, 0), std::sin(0.7), 1e-15);
}

// d/dt exp(theta(t)) must equal R * [w]x for the body-frame angular velocity w: step theta by
// h thetadot and compare with R * exp(h w) (central difference, error O(h^2)).
TEST(LimitedBushingLaw, RotationVectorRateMatchesBodyAngularVelocity) {
    const SimTK::Vec3 w(0.4, -1.1, 0.25);
    for (const SimTK::Vec3& theta : {SimTK::Vec3(0.3, -0.2, 0.9), SimTK::Vec3(2.0, 1.5, -1.0),
                                     SimTK::Vec3(1e-5, 0, 0), SimTK::Vec3(0)}) {
        const double h = 1e-5;
        const SimTK::Vec3 thetaDot = calcRotationVectorRate(theta, w);
        const SimTK::Rotation R = calcRotationFromVector(theta);
        const SimTK::Rotation ahead = calcRotationFromVector(theta + h * thetaDot);
        const SimTK::Rotation behind = calcRotationFromVector(theta - h * thetaDot);
        const SimTK::Rotation expectedAhead = R * calcRotationFromVector(h * w);
        const SimTK::Rotation expectedBehind = R * calcRotationFromVector(-h * w);
        EXPECT_TRUE(ahead.isSameRotationToWithinAngle(expectedAhead, 1e-9)) << theta;
        EXPECT_TRUE(behind.isSameRotationToWithinAngle(expectedBehind, 1e-9)) << theta;
    }
}

// The worst displacement of a point at the lever arm, every axis at |e_k| = L_k / K_k with the
// signs lined up: |e_p| + arm |e_r| = sqrt(3) (L_t / K_t + arm L_r / K_r) must equal the bound
// when both parts are stiffened, and stay below it when the minimum is the stiffer one.
TEST(LimitedBushingLaw, StiffnessForBoundKeepsTheWorstDisplacementWithinTheBound) {
    const double bound = 1e-4, arm = 0.03;
    const SimTK::Vec6 loads(0.04, 0.04, 0.04, 2.7, 2.7, 2.7);
    const SimTK::Vec6 soft(1, 1, 1, 10, 10, 10);
    const SimTK::Vec6 K = calcStiffnessForBound(soft, loads, arm, bound);
    const double worst = std::sqrt(3.0) * (loads[3] / K[3] + arm * loads[0] / K[0]);
    EXPECT_NEAR(worst, bound, 1e-12 * bound);
    EXPECT_NEAR(K[3], 2 * std::sqrt(3.0) * 2.7 / bound, 1e-9 * K[3]);

    const SimTK::Vec6 stiff(1e9, 1e9, 1e9, 1e9, 1e9, 1e9);
    EXPECT_EQ(calcStiffnessForBound(stiff, loads, arm, bound), stiff);
}

// Critical damping: the axis's characteristic polynomial J s^2 + D s + K (J = I_k on rotations,
// m on translations) has a double root, D^2 = 4 K J; with K = J w^2 that is D = 2 J w.
TEST(LimitedBushingLaw, CriticalDampingGivesADoubleRootOnEveryAxis) {
    const SimTK::Vec3 I(2e-5, 3e-5, 5e-5);
    const double m = 0.15, w = 200;
    const SimTK::Vec6 K(I[0] * w * w, I[1] * w * w, I[2] * w * w, m * w * w, m * w * w, 7.5);
    const SimTK::Vec6 D = calcCriticalDamping(K, I, m);
    for (int k = 0; k < 6; ++k) {
        const double J = k < 3 ? I[k] : m;
        EXPECT_NEAR(D[k] * D[k], 4 * K[k] * J, 1e-14 * D[k] * D[k]) << k;
    }
    EXPECT_NEAR(D[1], 2 * I[1] * w, 1e-15 * D[1]);
    EXPECT_NEAR(D[3], 2 * m * w, 1e-15 * D[3]);
    EXPECT_NEAR(D[5], 2 * std::sqrt(7.5 * m), 1e-15 * D[5]);
}

// Positive definiteness against Sylvester's criterion on 2 x 2 blocks: a diagonal d with one
// symmetric pair c is positive definite exactly when c^2 < d_i d_j.
TEST(LimitedBushingLaw, PositiveDefiniteIsSylvestersCriterion) {
    SimTK::Mat66 K;
    for (int r = 0; r < 6; ++r) {
        for (int c = 0; c < 6; ++c) K(r, c) = r == c ? 1.0 + r : 0.0;
    }
    EXPECT_TRUE(isPositiveDefinite(K));
    K(1, 4) = K(4, 1) = 0.999 * std::sqrt(2.0 * 5.0);
    EXPECT_TRUE(isPositiveDefinite(K));
    K(1, 4) = K(4, 1) = 1.001 * std::sqrt(2.0 * 5.0);
    EXPECT_FALSE(isPositiveDefinite(K));
    K(1, 4) = K(4, 1) = 0;
    K(5, 5) = 0;
    EXPECT_FALSE(isPositiveDefinite(K));
}

}  // namespace
}  // namespace graspsim::grasp
