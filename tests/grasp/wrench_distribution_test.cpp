// Distributing a wrench over contacts: closed-form oracles for a two-finger pinch (symmetry and
// equilibrium fix the split), the equilibrium equations themselves summed by hand, and Eigen's
// complete orthogonal decomposition as an independent pseudo-inverse.

#include "graspsim/grasp/wrench_distribution.h"

#include "graspsim/error.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <Eigen/Dense>

#include <algorithm>
#include <random>

using namespace graspsim;
using namespace graspsim::grasp;

namespace {

// Two fingers pinching across z at +-h, pushing inward, 5 cm from O along x.
constexpr double kHalfThickness = 0.004;  // m
const Eigen::Vector3d kPinchPoint(0.05, 0, 0);

std::vector<GraspContact> makePinch() {
    GraspContact below, above;
    below.p_GC = kPinchPoint - kHalfThickness * Eigen::Vector3d::UnitZ();
    below.n_G = Eigen::Vector3d::UnitZ();
    above.p_GC = kPinchPoint + kHalfThickness * Eigen::Vector3d::UnitZ();
    above.n_G = -Eigen::Vector3d::UnitZ();
    return {below, above};
}

std::vector<Eigen::Vector3d> makeSqueeze(double normalForce) {
    return {normalForce * Eigen::Vector3d::UnitZ(), -normalForce * Eigen::Vector3d::UnitZ()};
}

// [moment about O's origin; force] of a force F applied at point p (G).
Eigen::Matrix<double, 6, 1> wrenchOf(const Eigen::Vector3d& F, const Eigen::Vector3d& p, const ObjectFrame& O = {}) {
    Eigen::Matrix<double, 6, 1> w;
    w << (p - O.p_GO).cross(F), F;
    return w;
}

// O at the pinch point: forces along the pinch axis have no moment about it.
ObjectFrame makeFrameAtPinch() {
    ObjectFrame O;
    O.p_GO = kPinchPoint;
    return O;
}

}  // namespace

// Supporting a weight through the pinch point: by symmetry each finger carries half of it, in
// friction, and the squeeze is unchanged.
TEST(WrenchDistribution, PinchSharesATangentialLoadEquallyAndKeepsTheSqueeze) {
    const double squeeze = 2.0, weight = 1.0;
    const Eigen::Vector3d F(0, weight, 0);
    const WrenchDistribution d = distributeWrench(makePinch(), ObjectFrame(), wrenchOf(F, kPinchPoint), makeSqueeze(squeeze), 0.7);
    ASSERT_EQ(d.forces_G.size(), 2u);
    for (int i = 0; i < 2; ++i) {
        EXPECT_NEAR(d.normalForces[i], squeeze, 1e-9);
        EXPECT_NEAR(d.forces_G[i].y(), weight / 2, 1e-9);
    }
    EXPECT_NEAR(d.residual, 0, 1e-9);
}

// The forces reproduce the wrench: sum f_i and sum p_i x f_i, summed here by hand.
TEST(WrenchDistribution, ForcesInsideTheConesReproduceTheWrench) {
    const std::vector<GraspContact> contacts = makePinch();
    const Eigen::Vector3d F(0.3, -0.8, 0.4);
    const Eigen::Matrix<double, 6, 1> W = wrenchOf(F, kPinchPoint + Eigen::Vector3d(0, 0, 0.001));  // on the pinch axis: no torsion about it
    const WrenchDistribution d = distributeWrench(contacts, ObjectFrame(), W, makeSqueeze(5.0), 0.9);
    Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < contacts.size(); ++i) {
        force += d.forces_G[i];
        moment += contacts[i].p_GC.cross(d.forces_G[i]);
    }
    EXPECT_NEAR((force - F).norm(), 0, 1e-9);
    EXPECT_NEAR((moment - W.head<3>()).norm(), 0, 1e-9);
    EXPECT_NEAR(d.residual, 0, 1e-9);
}

// A pull along the pinch axis: each finger takes half, one presses harder, the other lets go
// (N -+ P/2); once P > 2N the far finger would have to pull, is clipped to zero, and the residual
// is what the near finger alone leaves unbalanced, P - (N + P/2) = P/2 - N.
TEST(WrenchDistribution, APullThroughThePinchUnloadsOneFingerAndIsClippedWhenItWouldPull) {
    const double squeeze = 1.0;
    for (const double pull : {1.5, 3.0}) {
        SCOPED_TRACE(pull);
        const Eigen::Vector3d F(0, 0, pull);
        const ObjectFrame O = makeFrameAtPinch();
        const WrenchDistribution d = distributeWrench(makePinch(), O, wrenchOf(F, kPinchPoint, O), makeSqueeze(squeeze), 0.5);
        EXPECT_NEAR(d.normalForces[0], squeeze + pull / 2, 1e-9);
        EXPECT_NEAR(d.normalForces[1], std::max(0.0, squeeze - pull / 2), 1e-9);
        EXPECT_NEAR(d.residual, std::max(0.0, pull / 2 - squeeze), 1e-9);
    }
}

// No reference (f0 = 0): the least-norm forces. A tangential load beyond mu times the (zero)
// squeeze cannot be carried in friction: both forces are clipped to zero, the whole load is residual.
TEST(WrenchDistribution, WithoutReferenceATangentialLoadHasNoSqueezeToRideOn) {
    const Eigen::Vector3d F(0, 1.0, 0);
    const ObjectFrame O = makeFrameAtPinch();
    const WrenchDistribution d = distributeWrench(makePinch(), O, wrenchOf(F, kPinchPoint, O), makeSqueeze(0), 0.7);
    EXPECT_NEAR(d.normalForces[0], 0, 1e-12);
    EXPECT_NEAR(d.normalForces[1], 0, 1e-12);
    EXPECT_NEAR(d.residual, 1.0, 1e-9);
}

TEST(WrenchDistribution, RejectsMismatchedReferencesAndNegativeFriction) {
    const Eigen::Matrix<double, 6, 1> W = Eigen::Matrix<double, 6, 1>::Zero();
    EXPECT_THROW(distributeWrench(makePinch(), ObjectFrame(), W, {Eigen::Vector3d::Zero()}, 0.5), InputError);
    EXPECT_THROW(distributeWrench(makePinch(), ObjectFrame(), W, makeSqueeze(1), -0.1), InputError);
}

// The least-norm split (zero references) is A^+ W; with each contact's normal along its own force
// no cone projection acts, so the forces are exactly that. A^+ from a complete orthogonal
// decomposition of the 6 x 3N map (rows: moment about O, then force) is the oracle. Random grasps of
// 3 to 8 contacts, and the degenerate ones: two contacts (no torsion about their line) and three on
// a line.
TEST(WrenchDistribution, AgreesWithAnOrthogonalDecompositionPseudoInverse) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const auto vec = [&] { return Eigen::Vector3d(unit(random), unit(random), unit(random)); };
    const auto check = [&](const std::vector<Eigen::Vector3d>& points) {
        ObjectFrame O;
        O.p_GO = 0.01 * vec();
        Eigen::MatrixXd A(6, 3 * static_cast<Eigen::Index>(points.size()));
        for (std::size_t i = 0; i < points.size(); ++i) {
            const Eigen::Vector3d r = points[i] - O.p_GO;
            Eigen::Matrix3d cross;
            cross << 0, -r.z(), r.y(), r.z(), 0, -r.x(), -r.y(), r.x(), 0;
            const Eigen::Index k = 3 * static_cast<Eigen::Index>(i);
            A.block<3, 3>(0, k) = cross;
            A.block<3, 3>(3, k) = Eigen::Matrix3d::Identity();
        }
        Eigen::Matrix<double, 6, 1> W;
        W << 0.05 * vec(), 2.0 * vec();
        const Eigen::VectorXd expected = A.completeOrthogonalDecomposition().solve(W);
        std::vector<GraspContact> contacts(points.size());
        for (std::size_t i = 0; i < points.size(); ++i) {
            contacts[i].p_GC = points[i];
            contacts[i].n_G = expected.segment<3>(3 * static_cast<Eigen::Index>(i)).normalized();
        }
        const WrenchDistribution d =
            distributeWrench(contacts, O, W, std::vector<Eigen::Vector3d>(points.size(), Eigen::Vector3d::Zero()), 0.5);
        for (std::size_t i = 0; i < points.size(); ++i) {
            const Eigen::Vector3d e = expected.segment<3>(3 * static_cast<Eigen::Index>(i));
            EXPECT_LT((d.forces_G[i] - e).norm(), 1e-9 * e.norm()) << points.size() << " contacts, contact " << i;
        }
    };
    for (int trial = 0; trial < 200; ++trial) {
        std::vector<Eigen::Vector3d> points(static_cast<std::size_t>(3 + trial % 6));
        for (Eigen::Vector3d& p : points) p = 0.05 * vec();
        check(points);
        const Eigen::Vector3d a = 0.05 * vec(), b = 0.05 * vec();
        check({a, b});
        check({a, b, 0.3 * a + 0.7 * b});
    }
}
