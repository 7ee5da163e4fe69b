#include "graspsim/grasp/rolling_stiffness.h"

#include "graspsim/error.h"

#include "pressing_contact.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>

namespace graspsim::grasp {
namespace {

using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;

CompliantContact makeContact(const Eigen::Vector3d& p_GC, const Eigen::Vector3d& n_G, double normalForce, double fingerCurvature,
                             double objectCurvature) {
    CompliantContact c = examples::makePressingContact(p_GC, n_G, normalForce, 1e4, 1e4);
    c.fingerCurvature = fingerCurvature;
    c.objectCurvature = objectCurvature;
    return c;
}

// A plate 2a thick pinched along x by two spherical pads of radius rho with force N: turned about
// an axis across the pinch the two forces form a couple -2 N (rho + a) theta (their lines of action
// through the pads' centres, along the turned faces' normal); about the pinch axis nothing changes.
TEST(RollingStiffness, APinchedPlateGainsTwoNTimesRhoPlusAAcrossThePinchAndNothingAboutIt) {
    for (const double rho : {0.005, 0.009}) {
        for (const double a : {0.002, 0.004}) {
            const double n = 1.7;
            const std::vector<CompliantContact> pinch{makeContact({-a, 0, 0}, {1, 0, 0}, n, 1 / rho, 0),
                                                      makeContact({a, 0, 0}, {-1, 0, 0}, n, 1 / rho, 0)};
            const Matrix6 g = calcRollingStiffness(pinch, Eigen::Vector3d::Zero());
            EXPECT_NEAR(g(5, 5), -2 * n * (rho + a), 1e-12);  // moment z per rotation z
            EXPECT_NEAR(g(4, 4), -2 * n * (rho + a), 1e-12);
            EXPECT_NEAR(g(3, 3), 0, 1e-12);                   // about the pinch axis
            EXPECT_NEAR((g.block<3, 3>(0, 3).norm()), 0, 1e-12);  // turning: the couple's forces cancel
        }
    }
}

// The exact wrench about the moved centre of mass of one contact whose force (normal only, fixed
// magnitude) lies on the line of the two surfaces' centres of curvature, the finger's fixed, the
// object's moved by delta = [dp ; theta]; a zero curvature is a flat surface.
Vector6 calcExactWrench(const CompliantContact& c, double normalForce, const Vector6& delta) {
    const double kf = c.fingerCurvature, ko = c.objectCurvature;
    const Eigen::Vector3d dp = delta.head<3>(), theta = delta.tail<3>();
    const Eigen::Matrix3d R = theta.norm() > 0 ? Eigen::AngleAxisd(theta.norm(), theta.normalized()).toRotationMatrix()
                                               : Eigen::Matrix3d::Identity();
    Eigen::Vector3d n, p_GC;
    if (ko == 0) {  // flat object face: the normal turns with the object, the pad's centre stays
        n = R * c.n_G;
        p_GC = c.p_GC - c.n_G / kf + n / kf;
    } else if (kf == 0) {  // flat pad: the normal stays, the object's centre of curvature moves
        n = c.n_G;
        p_GC = dp + R * (c.p_GC + c.n_G / ko) - n / ko;
    } else {
        const Eigen::Vector3d finger = c.p_GC - c.n_G / kf, object = dp + R * (c.p_GC + c.n_G / ko);
        n = (object - finger).normalized();
        p_GC = finger + n / kf;
    }
    const Eigen::Vector3d f = normalForce * n;
    Vector6 w;
    w << f, (p_GC - dp).cross(f);
    return w;
}

// G against central differences of the exact geometry, for a pad on a ball, a pad on a flat face
// and a ball on a flat pad, each at a point off the centre of mass with a tilted normal.
TEST(RollingStiffness, EqualsTheDerivativeOfTheExactRollingGeometry) {
    const Eigen::Vector3d p_GC(0.012, -0.03, 0.021), n_G = Eigen::Vector3d(0.3, 0.9, -0.2).normalized();
    for (const auto& [kf, ko] : std::vector<std::pair<double, double>>{{1 / 0.008, 1 / 0.045}, {1 / 0.008, 0}, {0, 1 / 0.03}}) {
        const CompliantContact c = makeContact(p_GC, n_G, 2.3, kf, ko);
        const Matrix6 g = calcRollingStiffness(c, c.force_G, Eigen::Vector3d::Zero());
        const double h = 1e-6;
        for (int k = 0; k < 6; ++k) {
            const Vector6 e = h * Vector6::Unit(k);
            const Vector6 column = (calcExactWrench(c, 2.3, e) - calcExactWrench(c, 2.3, -e)) / (2 * h);
            EXPECT_LT((g.col(k) - column).norm(), 1e-6 * (1 + column.norm())) << "kf " << kf << " ko " << ko << " column " << k;
        }
    }
}

TEST(RollingStiffness, ContactsWithoutCurvaturesAddNothingAndBadCurvaturesAreRefused) {
    const CompliantContact frozen = makeContact({0.01, 0, 0}, {-1, 0, 0}, 3, 0, 0);
    EXPECT_EQ(calcRollingStiffness(frozen, frozen.force_G, Eigen::Vector3d::Zero()), Matrix6::Zero());
    for (const double bad : {-1.0, std::nan("")}) {
        CompliantContact c = frozen;
        c.objectCurvature = bad;
        EXPECT_THROW(calcRollingStiffness(c, c.force_G, Eigen::Vector3d::Zero()), InputError);
    }
}

// In the compliance model a torque across the pinch turns the plate by T / (2 k_t a^2 + 2 N (rho +
// a)): the pads' tangential springs at +-a and the couple of the turned grip, in parallel.
TEST(RollingStiffness, TheComplianceModelTurnsAPinchedPlateByTheTorqueOverBothStiffnesses) {
    const double rho = 0.008, a = 0.004, n = 2.0, kt = 500;
    std::vector<CompliantContact> pinch{makeContact({-a, 0, 0}, {1, 0, 0}, n, 1 / rho, 0),
                                        makeContact({a, 0, 0}, {-1, 0, 0}, n, 1 / rho, 0)};
    for (CompliantContact& c : pinch) c.tangentialStiffness = kt;
    CompliantCapacityOptions options;
    options.mu = 1.0;
    options.maxLoad = 1e-4;  // N m: far inside the cones
    Vector6 torque = Vector6::Zero();
    torque[2] = 1;  // about z, rotation first
    std::vector<CompliantContact> frozenPinch = pinch;
    for (CompliantContact& c : frozenPinch) c.fingerCurvature = 0;
    const CompliantCapacity frozen = calcCompliantCapacity(frozenPinch, Eigen::Vector3d::Zero(), torque, options);
    const CompliantCapacity rolling = calcCompliantCapacity(pinch, Eigen::Vector3d::Zero(), torque, options);
    EXPECT_NEAR(frozen.displacement_G[2], options.maxLoad / (2 * kt * a * a), 1e-9 * options.maxLoad / (2 * kt * a * a));
    const double expected = options.maxLoad / (2 * kt * a * a + 2 * n * (rho + a));
    EXPECT_NEAR(rolling.displacement_G[2], expected, 1e-9 * expected);
}

}  // namespace
}  // namespace graspsim::grasp
