// Locked fingers that follow the object's give: the finger's share of a contact's motion, against
// the closed form of two springs in series.
#include "graspsim/simulation/finger_follow.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <limits>

namespace graspsim {
namespace {

grasp::CompliantContact makeContact(const Eigen::Vector3d& n, double kn, double kt, const Eigen::Matrix3d& fingerCompliance) {
    grasp::CompliantContact c;
    c.n_G = n.normalized();
    c.normalStiffness = kn;
    c.tangentialStiffness = kt;
    c.fingerCompliance_G = fingerCompliance;
    return c;
}

// Along the normal the finger (a) and the contact (1/k_n) are springs in series: the finger moves
// by a / (a + 1/k_n) of the object's motion; along each tangent by b / (b + 1/k_t).
TEST(FingerFollow, TheFingersShareIsItsSpringInSeriesWithTheContacts) {
    const Eigen::Matrix3d C_f = Eigen::Vector3d(1e-3, 2e-3, 5e-4).asDiagonal();
    const Eigen::Matrix3d share = simulation::calcFingerShare(makeContact(Eigen::Vector3d::UnitZ(), 2000, 1000, C_f));
    EXPECT_NEAR(share(0, 0), 1e-3 / (1e-3 + 1e-3), 1e-12);
    EXPECT_NEAR(share(1, 1), 2e-3 / (2e-3 + 1e-3), 1e-12);
    EXPECT_NEAR(share(2, 2), 5e-4 / (5e-4 + 5e-4), 1e-12);
    EXPECT_NEAR((share - Eigen::Matrix3d(share.diagonal().asDiagonal())).norm(), 0, 1e-12);
}

// Coupled: a finger compliance with off-diagonal terms and a slanted normal. The force through
// both springs is the same, so the finger's part of the motion is C_f f and the whole (C_f + C_c) f:
// share (C_f + C_c) = C_f.
TEST(FingerFollow, ACoupledFingerSharesTheMotionSoThatBothSpringsCarryOneForce) {
    Eigen::Matrix3d A;
    A << 3, 1, 0.5, 0, 2, 0.3, 0, 0, 1;
    const Eigen::Matrix3d C_f = 1e-3 * A * A.transpose();
    const grasp::CompliantContact c = makeContact(Eigen::Vector3d(0.3, -0.4, 0.87), 1500, 900, C_f);
    const Eigen::Matrix3d nn = c.n_G * c.n_G.transpose();
    const Eigen::Matrix3d C_c = nn / 1500 + (Eigen::Matrix3d::Identity() - nn) / 900;
    EXPECT_NEAR((simulation::calcFingerShare(c) * (C_f + C_c) - C_f).norm(), 0, 1e-12);
}

// A rigid finger does not move; a contact that does not give tangentially leaves the tangential
// motion to the finger, and the normal one shared.
TEST(FingerFollow, ARigidFingerStaysAndARigidContactPassesItsTangentialMotionOn) {
    EXPECT_NEAR(simulation::calcFingerShare(makeContact(Eigen::Vector3d::UnitX(), 1000, 700, Eigen::Matrix3d::Zero())).norm(), 0, 1e-15);
    const double inf = std::numeric_limits<double>::infinity();
    const Eigen::Matrix3d share = simulation::calcFingerShare(makeContact(Eigen::Vector3d::UnitX(), 1000, inf, 1e-3 * Eigen::Matrix3d::Identity()));
    EXPECT_NEAR(share(0, 0), 0.5, 1e-12);
    EXPECT_NEAR(share(1, 1), 1, 1e-12);
    EXPECT_NEAR(share(2, 2), 1, 1e-12);
}

}  // namespace
}  // namespace graspsim
