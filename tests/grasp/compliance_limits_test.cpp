// The compliance limits against the closed forms of the compliance model's two-finger pinch
// (compliant_grasp_capacity_test.cpp): across the pinch axis both sides are 2 mu N whatever weight
// the friction carries; along it the finger a load pulls away from lets go first, so the sides differ.
#include "graspsim/grasp/compliance_limits.h"

#include "graspsim/error.h"

#include "pressing_contact.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <string>

namespace graspsim::grasp {
namespace {

constexpr double kN = 5;      // N, each finger's press
constexpr double kMu = 0.6;
constexpr double kWeight = 2;  // N, carried by the two fingers' friction along +y
constexpr double kSlip = 1.5e-3;  // m

CompliantContact makeContact(const Eigen::Vector3d& p, const Eigen::Vector3d& n, double kn, double fingerCompliance,
                             double weight) {
    CompliantContact c = examples::makePressingContact(p, n, kN, kn, 2.0 / 3.0 * kn, fingerCompliance);
    c.force_G += Eigen::Vector3d(0, weight / 2, 0);
    return c;
}

// Finger A at -x pressing +x, finger B at +x pressing -x, soft: series normal stiffnesses
// kA = 1 / (1 / 3000 + 2e-4) = 1875 N/m and kB = 1 / (1 / 6000 + 1e-4) = 3750 N/m; no weight.
std::vector<CompliantContact> makeSoftPinch() {
    return {makeContact({-0.02, 0, 0}, {1, 0, 0}, 3000, 2e-4, 0), makeContact({0.02, 0, 0}, {-1, 0, 0}, 6000, 1e-4, 0)};
}

// The same pinch stiff enough (tangentially 25 000 and 50 000 N/m in series with the fingers) that
// its friction limit comes before the 1.5 mm onset, carrying kWeight.
std::vector<CompliantContact> makeStiffPinch() {
    return {makeContact({-0.02, 0, 0}, {1, 0, 0}, 5e4, 1e-5, kWeight), makeContact({0.02, 0, 0}, {-1, 0, 0}, 1e5, 5e-6, kWeight)};
}

ComplianceLimitOptions makeOptions() {
    ComplianceLimitOptions o;
    o.mu = kMu;
    o.slipDistance = kSlip;
    return o;
}

// Closed forms along the pinch axis x (the object moves s / (kA + kB) while both fingers press):
//  - a load +x pulls away from A: kA d = 2.8 N < N, so the 1.5 mm onset comes first: (kA + kB) d;
//  - a load -x pulls away from B: kB d = 5.6 N > N, so B opens at N (kA + kB) / kB = 7.5 N, then A
//    alone gives: N + kA d.
const double kA = 1875, kB = 3750;
const double kOnsetPlusX = (kA + kB) * kSlip;  // 8.4375 N
const double kOnsetMinusX = kN + kA * kSlip;   // 7.8125 N

TEST(ComplianceLimits, PinchAcrossItsAxisGivesTwiceMuNOnBothSidesWhateverTheWeight) {
    const TwoSidedLimits limits = calcComplianceLimits(makeStiffPinch(), Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), makeOptions());
    // Along y the load s shifts each finger's friction from W/2 to W/2 -+ s/2: the grasp slips at
    // s = W + 2 mu N upward and 2 mu N - W downward; less and plus the carried W, both sides are 2 mu N.
    EXPECT_NEAR(limits.lower[4], 2 * kMu * kN, 1e-9);
    EXPECT_NEAR(limits.upper[4], 2 * kMu * kN, 1e-9);
    // Along z each finger's friction turns: |(W/2, s/2)| reaches mu N at s = 2 sqrt((mu N)^2 - (W/2)^2).
    const double acrossWeight = 2 * std::sqrt(kMu * kN * kMu * kN - kWeight * kWeight / 4);
    EXPECT_NEAR(limits.lower[5], acrossWeight, 1e-9);
    EXPECT_NEAR(limits.upper[5], acrossWeight, 1e-9);
    // Two point contacts on the x axis carry no torque about it.
    EXPECT_EQ(limits.lower[0], 0);
    EXPECT_EQ(limits.upper[0], 0);
}

// With kinetic friction below static the pinch's sides across its axis stay 2 mu_s N: its two
// contacts reach the cone at the same load (equal shares), both break loose together, and the
// 2 mu_d N left cannot take up what they shed, so the grasp goes where mu_s says.
TEST(ComplianceLimits, PinchContactsBreakingLooseTogetherKeepTheStaticLimit) {
    ComplianceLimitOptions o = makeOptions();
    o.kineticMu = 0.5 * kMu;
    const TwoSidedLimits limits = calcComplianceLimits(makeStiffPinch(), Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), o);
    EXPECT_NEAR(limits.lower[4], 2 * kMu * kN, 1e-9);
    EXPECT_NEAR(limits.upper[4], 2 * kMu * kN, 1e-9);
}

TEST(ComplianceLimits, PinchAlongItsAxisIsAsymmetric) {
    const TwoSidedLimits limits = calcComplianceLimits(makeSoftPinch(), Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), makeOptions());
    // A load +x needs the force -s on the object: the lower side; a load -x the upper one.
    EXPECT_NEAR(limits.lower[3], kOnsetPlusX, 1e-9);
    EXPECT_NEAR(limits.upper[3], kOnsetMinusX, 1e-9);
}

// M turned 90 deg about z: M's x is G's y and M's y is G's -x, so M's x gets G's y limits and M's y
// G's x limits with the sides exchanged (likewise the rotations); the carried weight is along +x of
// M. Second method: the same grasp in G's axes.
TEST(ComplianceLimits, FollowTheConstraintFramesAxesAndSides) {
    const Eigen::Matrix3d R_GM = Eigen::AngleAxisd(0.5 * 3.14159265358979323846, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    for (const auto& pinch : {makeStiffPinch(), makeSoftPinch()}) {
        const TwoSidedLimits inG = calcComplianceLimits(pinch, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), makeOptions());
        const TwoSidedLimits inM = calcComplianceLimits(pinch, R_GM, Eigen::Vector3d::Zero(), makeOptions());
        const Eigen::Matrix<double, 6, 1> w0 = calcContactWrenchInM(pinch, R_GM, Eigen::Vector3d::Zero());
        EXPECT_NEAR(w0[3], pinch[0].force_G[1] + pinch[1].force_G[1], 1e-12);
        EXPECT_NEAR(w0[4], 0, 1e-12);
        for (int offset : {0, 3}) {
            EXPECT_NEAR(inM.lower[offset], inG.lower[offset + 1], 1e-9);
            EXPECT_NEAR(inM.upper[offset], inG.upper[offset + 1], 1e-9);
            EXPECT_NEAR(inM.lower[offset + 1], inG.upper[offset], 1e-9);
            EXPECT_NEAR(inM.upper[offset + 1], inG.lower[offset], 1e-9);
            EXPECT_NEAR(inM.lower[offset + 2], inG.lower[offset + 2], 1e-9);
        }
    }
}

TEST(ComplianceLimits, SidesAreCappedAtTheLargestLoadAndBadOptionsRejected) {
    ComplianceLimitOptions o = makeOptions();
    o.maxLoads[3] = 5;
    const TwoSidedLimits limits = calcComplianceLimits(makeSoftPinch(), Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), o);
    EXPECT_EQ(limits.lower[3], 5);
    EXPECT_EQ(limits.upper[3], 5);
    o.maxLoads[2] = 0;
    try {
        calcComplianceLimits(makeSoftPinch(), Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), o);
        FAIL() << "a zero largest load was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("axis 2"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace graspsim::grasp
