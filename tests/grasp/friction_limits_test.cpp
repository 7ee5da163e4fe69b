#include "graspsim/grasp/friction_limits.h"

#include "graspsim/error.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <random>

namespace graspsim::grasp {
namespace {

constexpr double kPi = 3.14159265358979323846;

GraspContact makeContact(const Eigen::Vector3d& p, const Eigen::Vector3d& n, double normalForce) {
    GraspContact c;
    c.p_GC = p;
    c.n_G = n.normalized();
    c.normalForce = normalForce;
    return c;
}

// Second method: the largest load along or about one axis, by brute force over friction forces
// sampled on each contact's friction circle (the contacts are independent, so each one's best
// sample adds up). It converges to the closed form from below.
Eigen::Matrix<double, 6, 1> sampleLimits(const std::vector<GraspContact>& contacts, double mu, const Eigen::Matrix3d& R_GM,
                                         const Eigen::Vector3d& p_GM) {
    Eigen::Matrix<double, 6, 1> limits = Eigen::Matrix<double, 6, 1>::Zero();
    constexpr int kSamples = 20000;
    for (const GraspContact& c : contacts) {
        const Eigen::Vector3d n = c.n_G;
        const Eigen::Vector3d t1 = n.unitOrthogonal(), t2 = n.cross(t1);
        Eigen::Matrix<double, 6, 1> best = Eigen::Matrix<double, 6, 1>::Zero();
        for (int s = 0; s < kSamples; ++s) {
            const double angle = 2 * kPi * s / kSamples;
            const Eigen::Vector3d f = mu * c.normalForce * (std::cos(angle) * t1 + std::sin(angle) * t2);
            const Eigen::Vector3d torque = (c.p_GC - p_GM).cross(f);
            for (int k = 0; k < 3; ++k) {
                best[k] = std::max(best[k], torque.dot(R_GM.col(k)));
                best[3 + k] = std::max(best[3 + k], f.dot(R_GM.col(k)));
            }
        }
        limits += best;
    }
    return limits;
}

TEST(FrictionLimits, TwoFingerPinchCarriesNoForceAlongNorTorqueAboutItsAxis) {
    // Pads at z = +-d push along -+z (into the object); M at their midpoint.
    const double d = 0.004, N = 3.0, mu = 0.7;
    const std::vector<GraspContact> contacts{makeContact({0, 0, d}, {0, 0, -1}, N), makeContact({0, 0, -d}, {0, 0, 1}, N)};
    const auto L = calcContactGeometryLimits(contacts, mu, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero());
    EXPECT_NEAR(L[0], 2 * mu * N * d, 1e-15);  // about x: the finger separation is the lever
    EXPECT_NEAR(L[1], 2 * mu * N * d, 1e-15);
    EXPECT_NEAR(L[2], 0, 1e-15);  // about the pinch axis: point contacts have no torsion
    EXPECT_NEAR(L[3], 2 * mu * N, 1e-15);
    EXPECT_NEAR(L[4], 2 * mu * N, 1e-15);
    EXPECT_NEAR(L[5], 0, 1e-15);  // along the pinch axis friction gives nothing
}

TEST(FrictionLimits, RingAroundAnAxisCarriesTheThesisForceAlongItAndLessAcross) {
    // n contacts evenly on a circle of radius R in the xy plane, normals toward the centre.
    const int n = 6;
    const double R = 0.045, N = 2.0, mu = 0.5;
    std::vector<GraspContact> contacts;
    for (int i = 0; i < n; ++i) {
        const double angle = 2 * kPi * i / n;
        const Eigen::Vector3d p(R * std::cos(angle), R * std::sin(angle), 0);
        contacts.push_back(makeContact(p, -p, N));
    }
    const auto L = calcContactGeometryLimits(contacts, mu, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero());
    EXPECT_NEAR(L[5], mu * n * N, 1e-12);      // along z every contact's friction helps fully
    EXPECT_NEAR(L[2], mu * n * N * R, 1e-12);  // about z: every contact with lever R
    // Along x: sum |sin| over the six angles = 4 sin 60 deg.
    EXPECT_NEAR(L[3], mu * N * 4 * std::sin(kPi / 3), 1e-12);
}

TEST(FrictionLimits, AgreeWithSampledFrictionForcesForRandomGrasps) {
    std::mt19937 random(11);
    std::uniform_real_distribution<double> unit(-1, 1), force(0.5, 5);
    for (int trial = 0; trial < 5; ++trial) {
        std::vector<GraspContact> contacts;
        for (int i = 0; i < 4; ++i) {
            const Eigen::Vector3d p = 0.05 * Eigen::Vector3d(unit(random), unit(random), unit(random));
            contacts.push_back(makeContact(p, Eigen::Vector3d(unit(random), unit(random), unit(random)), force(random)));
        }
        const Eigen::Matrix3d R_GM =
            Eigen::AngleAxisd(unit(random) * kPi, Eigen::Vector3d(unit(random), unit(random), unit(random)).normalized())
                .toRotationMatrix();
        const Eigen::Vector3d p_GM = 0.01 * Eigen::Vector3d(unit(random), unit(random), unit(random));
        const auto closed = calcContactGeometryLimits(contacts, 0.8, R_GM, p_GM);
        const auto sampled = sampleLimits(contacts, 0.8, R_GM, p_GM);
        for (int k = 0; k < 6; ++k) {
            EXPECT_LE(sampled[k], closed[k] + 1e-12) << trial << " axis " << k;
            EXPECT_NEAR(sampled[k], closed[k], 1e-6 * (1 + closed[k])) << trial << " axis " << k;
        }
    }
}

TEST(FrictionLimits, ModelNamesParseAndBadFrictionIsRefused) {
    EXPECT_EQ(parseFrictionLimitModel("contact", "--limits"), FrictionLimitModel::ContactGeometry);
    EXPECT_EQ(toString(parseFrictionLimitModel("thesis", "--limits")), "thesis");
    EXPECT_THROW(parseFrictionLimitModel("box", "--limits"), InputError);
    EXPECT_THROW(calcContactGeometryLimits({}, -0.1, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero()), InputError);
}

}  // namespace
}  // namespace graspsim::grasp
