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

// Followed step by step, the model is the ramp: the ring's ramp given to CompliantCreep as 10 ms
// pieces reaches the ramp's slip at every piece's end (runCompliantRamp, the second method, takes
// the same steps in one loop) and gives way at the ramp's ultimate load.
TEST(CompliantGraspCreep, FollowedPieceByPieceItIsTheRamp) {
    std::vector<CompliantContact> ring;
    const double N = 3, R = 0.04, rate = 6;
    for (int k = 0; k < 5; ++k) {
        const double angle = 2 * kPi * k / 5;
        const Eigen::Vector3d p(R * std::cos(angle), 0.01, R * std::sin(angle));
        ring.push_back(examples::makePressingContact(p, -p.normalized(), N, 4000, 4e4));
        ring.back().fingerCompliance_G = 3e-4 * Eigen::Matrix3d::Identity();
    }
    CompliantRampOptions options;
    options.rate = rate;
    options.maxLoad = 30;
    options.slipDistance = 1;
    const CompliantRamp ramp = runCompliantRamp(ring, Eigen::Vector3d::Zero(), force({0, -1, 0}), makeFriction(0.9, 0.7), options);
    ASSERT_TRUE(std::isfinite(ramp.capacity.ultimate));
    CompliantCreep creep(ring, Eigen::Vector3d::Zero(), makeFriction(0.9, 0.7));
    std::size_t piece = 0;
    while (creep.advance(force({0, -rate * 0.01, 0}), 0.01, options.timeStep)) {
        ++piece;
        ASSERT_LT(10 * piece, ramp.samples.size());
        EXPECT_NEAR(creep.findSlip(), ramp.samples[10 * piece].slip, 1e-9 + 1e-9 * ramp.samples[10 * piece].slip) << "piece " << piece;
    }
    EXPECT_TRUE(creep.hasGivenWay());
    EXPECT_NEAR(0.01 * rate * static_cast<double>(piece), ramp.capacity.ultimate, 0.01 * rate + 1e-9);
}

// A load step, then held: taken up elastically by the two tangential springs, x = F / (2 k_t), then
// each contact, carrying F / 2 at a constant share of its cone, creeps at the law's v = v_tr F / (2
// mu N) (mu_s = mu_d: mu v / v_tr below v_tr): x(T) = F / (2 k_t) + v_tr F T / (2 mu N). Measured at a
// slip point on the load's line, away from the contacts.
TEST(CompliantGraspCreep, AStepThenHeldCreepsAsTheClosedForm) {
    const double N = 5, kt = 2e4, mu = 0.6, v_tr = 1e-3, F = 0.5 * 2 * mu * N, T = 0.3;
    const std::vector<CompliantContact> pinch = {examples::makePressingContact({-0.02, 0, 0}, {1, 0, 0}, N, 3000, kt),
                                                 examples::makePressingContact({0.02, 0, 0}, {-1, 0, 0}, N, 3000, kt)};
    CompliantCreep creep(pinch, Eigen::Vector3d::Zero(), makeFriction(mu, mu), {Eigen::Vector3d(0, 0.05, 0)});
    ASSERT_TRUE(creep.advance(force({0, F, 0}), 0));
    EXPECT_NEAR(creep.findSlip(), F / (2 * kt), 1e-6 * F / (2 * kt));
    ASSERT_TRUE(creep.advance(Vector6::Zero(), T, 1e-4));
    const double expected = F / (2 * kt) + v_tr * F * T / (2 * mu * N);
    EXPECT_NEAR(creep.findSlip(), expected, 2e-3 * expected);
    const CompliantCreep copy = creep;  // the state so far, carried on alike
    CompliantCreep other = copy;
    ASSERT_TRUE(creep.advance(Vector6::Zero(), 0.1));
    ASSERT_TRUE(other.advance(Vector6::Zero(), 0.1));
    EXPECT_EQ(creep.findSlip(), other.findSlip());
    EXPECT_GT(creep.findSlip(), copy.findSlip());
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
    EXPECT_THROW(CompliantCreep(one, Eigen::Vector3d::Zero(), viscous), InputError);
    CompliantCreep creep(one, Eigen::Vector3d::Zero(), makeFriction(0.9, 0.7));
    EXPECT_THROW(creep.advance(force({0, NAN, 0}), 0.01), InputError);
    EXPECT_THROW(creep.advance(force({0, 1, 0}), -0.01), InputError);
    EXPECT_THROW(creep.advance(force({0, 1, 0}), 0.01, 0), InputError);
}

}  // namespace
}  // namespace graspsim::grasp
