#include "graspsim/grasp/compliant_grasp_creep.h"

#include "graspsim/error.h"

#include "pressing_contact.h"

#include <gtest/gtest.h>

#include <cmath>

namespace graspsim::grasp {
namespace {

constexpr double kPi = 3.14159265358979323846;
using Vector6 = Eigen::Matrix<double, 6, 1>;


Vector6 force(const Eigen::Vector3d& f) {
    Vector6 w = Vector6::Zero();
    w.tail<3>() = f;
    return w;
}

contact::ContactParameters makeFriction(double mu_s, double mu_d) {
    contact::ContactParameters p;
    p.staticFriction = mu_s;
    p.dynamicFriction = mu_d;
    p.transitionVelocity = 1e-3;
    return p;
}

// Two rigid fingers squeeze with N across x; a load F = R t along y is shared equally. With
// mu_s = mu_d = mu the regularized law is mu v / v_tr below v_tr, so each contact creeps at
// v = v_tr F / (2 mu N) and its tangential spring gives F / (2 k_t): the object has moved
// x(F) = F / (2 k_t) + v_tr F^2 / (4 mu N R), until both contacts break loose at F = 2 mu N.
TEST(CompliantGraspCreep, SqueezeCreepsAsTheClosedForm) {
    const double N = 5, kt = 2e4, R = 1, mu = 0.6, v_tr = 1e-3;
    const std::vector<CompliantContact> pinch = {examples::makePressingContact({-0.02, 0, 0}, {1, 0, 0}, N, 3000, kt),
                                                 examples::makePressingContact({0.02, 0, 0}, {-1, 0, 0}, N, 3000, kt)};
    CompliantRampOptions options;
    options.rate = R;
    options.timeStep = 1e-4;
    options.slipDistance = 2e-3;
    options.maxLoad = 20;
    const CompliantRamp ramp = runCompliantRamp(pinch, Eigen::Vector3d::Zero(), force({0, 1, 0}), makeFriction(mu, mu), options);
    for (const CompliantRampSample& s : ramp.samples) {
        if (s.load < 0.5) continue;
        const double expected = s.load / (2 * kt) + v_tr * s.load * s.load / (4 * mu * N * R);
        ASSERT_NEAR(s.slip, expected, 5e-3 * expected) << "load " << s.load;
    }
    const double d = options.slipDistance, a = v_tr / (4 * mu * N * R), b = 1 / (2 * kt);
    const double onset = (-b + std::sqrt(b * b + 4 * a * d)) / (2 * a);  // 4.75 N, below 2 mu N = 6 N
    EXPECT_NEAR(ramp.capacity.onset, onset, 5e-3 * onset);
    EXPECT_NEAR(ramp.capacity.firstSlip, 2 * mu * N, R * options.timeStep + 1e-9);
    EXPECT_NEAR(ramp.capacity.ultimate, 2 * mu * N, R * options.timeStep + 1e-9);
}

// A ring of equal contacts loaded along its axis: every contact carries F / n and breaks loose at
// F = n mu_s N; the drop to mu_d leaves nothing to take it (they all go at once): ultimate n mu_s N.
TEST(CompliantGraspCreep, RingBreaksLooseAtTheStaticPeak) {
    std::vector<CompliantContact> ring;
    const double N = 3, R = 0.04;
    for (int k = 0; k < 5; ++k) {
        const double angle = 2 * kPi * k / 5;
        const Eigen::Vector3d p(R * std::cos(angle), 0, R * std::sin(angle));
        ring.push_back(examples::makePressingContact(p, -p, N, 4000, 4e4));
        ring.back().fingerCompliance_G = 3e-4 * Eigen::Matrix3d::Identity();
    }
    CompliantRampOptions options;
    options.rate = 6;
    options.maxLoad = 30;
    const CompliantRamp ramp = runCompliantRamp(ring, Eigen::Vector3d::Zero(), force({0, -1, 0}), makeFriction(0.9, 0.7), options);
    EXPECT_NEAR(ramp.capacity.ultimate, 5 * 0.9 * N, 2 * options.rate * options.timeStep);
    EXPECT_LE(ramp.capacity.onset, ramp.capacity.ultimate);
}

TEST(CompliantGraspCreep, RejectsBadInput) {
    const std::vector<CompliantContact> one = {examples::makePressingContact({0.02, 0, 0}, {-1, 0, 0}, 5, 3000, 3e4)};
    CompliantRampOptions options;
    EXPECT_THROW(runCompliantRamp(one, Eigen::Vector3d::Zero(), force({0, 0.5, 0}), makeFriction(0.9, 0.7), options), InputError);
    options.rate = 0;
    EXPECT_THROW(runCompliantRamp(one, Eigen::Vector3d::Zero(), force({0, 1, 0}), makeFriction(0.9, 0.7), options), InputError);
    options.rate = 1;
    contact::ContactParameters viscous = makeFriction(0.9, 0.7);
    viscous.viscousFriction = 0.1;
    EXPECT_THROW(runCompliantRamp(one, Eigen::Vector3d::Zero(), force({0, 1, 0}), viscous, options), InputError);
}

}  // namespace
}  // namespace graspsim::grasp
