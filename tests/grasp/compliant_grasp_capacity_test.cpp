#include "graspsim/grasp/compliant_grasp_capacity.h"

#include "graspsim/error.h"
#include "graspsim/grasp/compliant_grasp_creep.h"
#include "graspsim/grasp/friction_limits.h"

#include "pressing_contact.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace graspsim::grasp {
namespace {

constexpr double kPi = 3.14159265358979323846;
using Vector6 = Eigen::Matrix<double, 6, 1>;

CompliantContact makeContact(const Eigen::Vector3d& p, const Eigen::Vector3d& n, double normalForce, double kn,
                             double fingerCompliance) {
    return examples::makePressingContact(p, n, normalForce, kn, 2.0 / 3.0 * kn, fingerCompliance);
}

Vector6 force(const Eigen::Vector3d& f) {
    Vector6 w = Vector6::Zero();
    w.tail<3>() = f;
    return w;
}

Vector6 torque(const Eigen::Vector3d& t) {
    Vector6 w = Vector6::Zero();
    w.head<3>() = t;
    return w;
}

// Two fingers squeeze the object along x from (-d, 0, 0) and (d, 0, 0), each pressing with N.
std::vector<CompliantContact> makePinch(double N, double kA, double kB, double cA, double cB) {
    const double d = 0.02;
    return {makeContact({-d, 0, 0}, {1, 0, 0}, N, kA, cA), makeContact({d, 0, 0}, {-1, 0, 0}, N, kB, cB)};
}

TEST(CompliantGraspCapacity, PinchCarriesTwiceMuNAcrossItsAxis) {
    for (double mu : {0.3, 0.9}) {
        for (double N : {2.0, 10.0}) {
            CompliantCapacityOptions options;
            options.mu = mu;
            // Unequal fingers: still equal shares, since the moment about z of a force at the centre
            // must vanish (two point contacts are statically determinate across the axis).
            const auto pinch = makePinch(N, 3000, 5000, 2e-4, 5e-4);
            for (const Eigen::Vector3d& e : {Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, -1)}) {
                const CompliantCapacity c = calcCompliantCapacity(pinch, Eigen::Vector3d::Zero(), force(e), options);
                EXPECT_NEAR(c.ultimate, 2 * mu * N, 1e-9 * N) << "mu " << mu << " N " << N;
                EXPECT_NEAR(c.firstSlip, c.ultimate, 1e-9 * N);
            }
        }
    }
}

TEST(CompliantGraspCapacity, EqualPinchFingersSlideTogether) {
    CompliantCapacityOptions options;
    options.mu = 0.6;
    const auto pinch = makePinch(5, 4000, 4000, 3e-4, 3e-4);
    const CompliantCapacity c = calcCompliantCapacity(pinch, Eigen::Vector3d::Zero(), force({0, -1, 0}), options);
    EXPECT_NEAR(c.firstSlip, 2 * 0.6 * 5, 1e-9);
    EXPECT_NEAR(c.ultimate, 2 * 0.6 * 5, 1e-9);
}

// Along the pinch axis the load is taken by the two fingers' normal springs in series with their
// arms: the finger it pulls away from unloads by k_A / (k_A + k_B) of the load and lets go at
// N (k_A + k_B) / k_A; the object moves F / (k_A + k_B) until then.
TEST(CompliantGraspCapacity, PinchAxisLoadUnloadsOneFinger) {
    const double N = 5, knA = 3000, knB = 6000, cA = 2e-4, cB = 1e-4;
    const double kA = 1 / (1 / knA + cA), kB = 1 / (1 / knB + cB);
    CompliantCapacityOptions options;
    options.mu = 0.7;
    options.slipDistance = 0.5e-3;
    const CompliantCapacity c =
        calcCompliantCapacity(makePinch(N, knA, knB, cA, cB), Eigen::Vector3d::Zero(), force({1, 0, 0}), options);
    ASSERT_FALSE(c.events.empty());
    EXPECT_EQ(c.events.front().contact, 0);
    EXPECT_EQ(c.events.front().state, CompliantContactState::Open);
    EXPECT_NEAR(c.events.front().load, N * (kA + kB) / kA, 1e-9);
    EXPECT_NEAR(c.onset, options.slipDistance * (kA + kB), 1e-9);
    // After the separation finger B alone pushes back: no friction limit is reached along x.
    EXPECT_TRUE(std::isinf(c.ultimate));
}

// Followed to a load below the first event, the model ends where its springs put the object:
// along the pinch axis F / (k_A + k_B), across it F / (k_t,A' + k_t,B') with each finger's
// tangential chain 1 / (1 / k_t + c), and no rotation (the pinch is symmetric about its centre).
TEST(CompliantGraspCapacity, DisplacementAtTheEndLoadIsTheSpringsDeflection) {
    const double N = 5, kn = 4000, c = 2e-4, F = 0.5;
    const double kNormal = 1 / (1 / kn + c), kTangential = 1 / (1 / (2.0 / 3.0 * kn) + c);
    CompliantCapacityOptions options;
    options.maxLoad = 1;
    const auto pinch = makePinch(N, kn, kn, c, c);
    const CompliantCapacity along = calcCompliantCapacityAlong(pinch, Eigen::Vector3d::Zero(), force({F, 0, 0}), options);
    Vector6 expected = Vector6::Zero();
    expected[3] = F / (2 * kNormal);
    EXPECT_LT((along.displacement_G - expected).norm(), 1e-12) << along.displacement_G.transpose();
    const CompliantCapacity across = calcCompliantCapacityAlong(pinch, Eigen::Vector3d::Zero(), force({0, 0, -F}), options);
    expected.setZero();
    expected[5] = -F / (2 * kTangential);
    EXPECT_LT((across.displacement_G - expected).norm(), 1e-12) << across.displacement_G.transpose();
    for (std::size_t i = 0; i < 2; ++i) EXPECT_NEAR(across.forces_G[i].z(), F / 2, 1e-12);  // balancing the load
}

TEST(CompliantGraspCapacity, NoTorqueAboutThePinchAxis) {
    CompliantCapacityOptions options;
    const CompliantCapacity c =
        calcCompliantCapacity(makePinch(5, 4000, 4000, 3e-4, 3e-4), Eigen::Vector3d::Zero(), torque({1, 0, 0}), options);
    EXPECT_EQ(c.ultimate, 0);
}

// A ring of contacts in the xz-plane, pressing toward its centre, opposite contacts alike (so the
// grasp is symmetric under the inversion r -> -r and a load at the centre only translates or turns
// it). A load along the ring's axis y, or a torque about it, is tangent at every contact: the normal
// forces cannot change and each contact ends sliding along the load, so the compliance model must
// give friction_limits' per-axis limit exactly (mu sum N_i and mu R sum N_i), whatever the
// stiffness; the first slip comes when the equal shares reach the weakest contact's mu N_min.
TEST(CompliantGraspCapacity, RingAlongItsAxisAgreesWithFrictionLimits) {
    const double R = 0.04, mu = 0.8;
    const double forces[] = {2, 5, 3.5};
    const double compliances[] = {0, 5e-4};  // rigid fingers and soft ones
    for (double compliance : compliances) {
        std::vector<CompliantContact> ring;
        std::vector<GraspContact> plain;
        for (int k = 0; k < 6; ++k) {
            const double angle = 2 * kPi * k / 6;
            const Eigen::Vector3d p(R * std::cos(angle), 0, R * std::sin(angle));
            ring.push_back(makeContact(p, -p, forces[k % 3], 5000, compliance));
            plain.push_back(GraspContact{p, -p.normalized(), forces[k % 3], Eigen::Vector3d::Zero()});
        }
        const auto limits = calcContactGeometryLimits(plain, mu, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero());
        CompliantCapacityOptions options;
        options.mu = mu;
        const CompliantCapacity along = calcCompliantCapacity(ring, Eigen::Vector3d::Zero(), force({0, 1, 0}), options);
        EXPECT_NEAR(along.ultimate, limits[4], 1e-9);
        EXPECT_NEAR(along.ultimate, mu * 2 * (2 + 5 + 3.5), 1e-9);
        EXPECT_NEAR(along.firstSlip, 6 * mu * 2, 1e-9);
        const CompliantCapacity about = calcCompliantCapacity(ring, Eigen::Vector3d::Zero(), torque({0, -1, 0}), options);
        EXPECT_NEAR(about.ultimate, limits[1], 1e-9);
        EXPECT_NEAR(about.ultimate, mu * R * 2 * (2 + 5 + 3.5), 1e-9);
    }
}

// Closed form for a symmetric grasp with tangential give: the ring's translation along its axis is
// F / (n k) with k = 1 / (c_f + 1 / k_t) per contact while all stick.
TEST(CompliantGraspCapacity, RingOnsetFromSeriesStiffness) {
    const double R = 0.04, N = 4, kn = 6000, cf = 4e-4;
    std::vector<CompliantContact> ring;
    for (int k = 0; k < 4; ++k) {
        const double angle = 2 * kPi * k / 4;
        const Eigen::Vector3d p(R * std::cos(angle), 0, R * std::sin(angle));
        ring.push_back(makeContact(p, -p, N, kn, cf));
    }
    CompliantCapacityOptions options;
    options.mu = 0.9;
    options.slipDistance = 1e-3;
    const double k = 1 / (cf + 1 / (2.0 / 3.0 * kn));
    const CompliantCapacity c = calcCompliantCapacity(ring, Eigen::Vector3d::Zero(), force({0, -1, 0}), options);
    EXPECT_NEAR(c.onset, 4 * k * options.slipDistance, 1e-9);  // 6.0 N, below 4 mu N = 14.4 N
    EXPECT_NEAR(c.ultimate, 4 * 0.9 * N, 1e-9);
}

// Static and kinetic friction (break loose at mu_s, slide at mu_d): a ring of four contacts in the
// xz-plane, a weak opposite pair (N_a, on x) and a strong one (N_b, on z), all with the same
// tangential stiffness k = 1 / (c_f + 1 / k_t), loaded along its axis y (tangent everywhere, so no
// normal force changes). Closed forms: equal shares F / 4 while all stick, so the weak pair breaks
// loose at F1 = 4 mu_s N_a; its friction drops to mu_d N_a, and the strong pair takes up the
// 2 (mu_s - mu_d) N_a it shed at the same load (the ring jumps (mu_s - mu_d) N_a / k); from there
// the strong pair alone carries the load beyond the weak pair's 2 mu_d N_a and breaks loose at
// F2 = 2 mu_d N_a + 2 mu_s N_b, after which the ring holds only 2 mu_d (N_a + N_b) < F2: the
// ultimate. If the take-up alone brings the strong pair to its cone (mu_s N_a + (mu_s - mu_d) N_a
// >= mu_s N_b), everything goes at F1.
std::vector<CompliantContact> makeTwoLevelRing(double weak, double strong, double kn, double cf) {
    const double R = 0.04;
    std::vector<CompliantContact> ring;
    for (int k = 0; k < 4; ++k) {
        const double angle = 0.5 * kPi * k;
        const Eigen::Vector3d p(R * std::cos(angle), 0, R * std::sin(angle));
        ring.push_back(makeContact(p, -p, k % 2 == 0 ? weak : strong, kn, cf));
    }
    return ring;
}

TEST(CompliantGraspCapacity, KineticFrictionSheddingIsTakenUpAtTheSameLoad) {
    const double muS = 0.9, muD = 0.6, Na = 2, Nb = 5, kn = 6000, cf = 4e-4;
    const double k = 1 / (cf + 1 / (2.0 / 3.0 * kn));
    const double F1 = 4 * muS * Na, F2 = 2 * muD * Na + 2 * muS * Nb;  // 7.2 N, 11.4 N
    const double atF1 = F1 / (4 * k), jump = (muS - muD) * Na / k;  // 1.17 mm, 0.39 mm
    CompliantCapacityOptions options;
    options.mu = muS;
    options.kineticMu = muD;
    options.slipDistance = 2e-3;  // after the jump: x = atF1 + jump + (F - F1) / (2 k)
    const auto ring = makeTwoLevelRing(Na, Nb, kn, cf);
    const CompliantCapacity c = calcCompliantCapacity(ring, Eigen::Vector3d::Zero(), force({0, -1, 0}), options);
    EXPECT_NEAR(c.firstSlip, F1, 1e-9);
    EXPECT_NEAR(c.ultimate, F2, 1e-9);
    EXPECT_NEAR(c.onset, F1 + (options.slipDistance - atF1 - jump) * 2 * k, 1e-9);  // 8.55 N
    options.slipDistance = 0.5 * (2 * atF1 + jump);  // reached during the take-up: at F1
    EXPECT_NEAR(calcCompliantCapacity(ring, Eigen::Vector3d::Zero(), force({0, -1, 0}), options).onset, F1, 1e-9);
    // Without the drop (kineticMu = mu, or unset) all four slide only at mu_s (N_a + N_b) each pair.
    options.kineticMu = muS;
    EXPECT_NEAR(calcCompliantCapacity(ring, Eigen::Vector3d::Zero(), force({0, -1, 0}), options).ultimate, 2 * muS * (Na + Nb), 1e-9);
    // A strong pair too weak for the take-up (mu_s Na + (mu_s - mu_d) Na = 2.4 N >= mu_s Nb = 2.25 N)
    // breaks loose during it: the cascade ends the grasp at F1.
    options.kineticMu = muD;
    const CompliantCapacity cascade = calcCompliantCapacity(makeTwoLevelRing(Na, 2.5, kn, cf), Eigen::Vector3d::Zero(), force({0, -1, 0}), options);
    EXPECT_NEAR(cascade.ultimate, F1, 1e-9);
    EXPECT_EQ(cascade.events.size(), 4u);
}

// kineticMu equal to mu is the single-coefficient model bit for bit, on a grasp where contacts slide
// one after another and open (the ring of six with unequal forces, loaded across its axis).
TEST(CompliantGraspCapacity, KineticFrictionEqualToMuChangesNothing) {
    std::vector<CompliantContact> ring;
    for (int k = 0; k < 6; ++k) {
        const double angle = 2 * kPi * k / 6 + 0.3;
        const Eigen::Vector3d p(0.04 * std::cos(angle), 0.01 * k, 0.04 * std::sin(angle));
        ring.push_back(makeContact(p, -Eigen::Vector3d(p.x(), 0, p.z()), 2 + k, 4000 + 500 * k, 3e-4));
    }
    for (const Vector6& load : {force({1, 0, 0}), force({0, 0, -1}), torque({0, 1, 0}), torque({1, 0, 0})}) {
        CompliantCapacityOptions options;
        options.mu = 0.8;
        const CompliantCapacity single = calcCompliantCapacity(ring, Eigen::Vector3d::Zero(), load, options);
        options.kineticMu = 0.8;
        const CompliantCapacity both = calcCompliantCapacity(ring, Eigen::Vector3d::Zero(), load, options);
        EXPECT_EQ(single.onset, both.onset);
        EXPECT_EQ(single.ultimate, both.ultimate);
        EXPECT_EQ(single.events.size(), both.events.size());
    }
}

// Where the slip is measured: a torque T about z twists the pinch (contacts at x = +-d) by
// theta = T / (2 k d^2), k = 1 / (c_f + 1 / k_t) each contact's tangential stiffness along y, and moves
// a material point at distance rho from the z axis by rho theta. At the contacts (rho = d) the
// onset is 2 k d s; at a goal point twice as far out, k d s; on the axis the slip never comes.
TEST(CompliantGraspCapacity, OnsetIsMeasuredAtTheSlipPoints) {
    const double N = 5, kn = 4000, cf = 3e-4, d = 0.02;
    const double k = 1 / (cf + 1 / (2.0 / 3.0 * kn));
    CompliantCapacityOptions options;
    options.mu = 5;  // no contact slides before the onsets below
    options.slipDistance = 1e-3;
    const auto pinch = makePinch(N, kn, kn, cf, cf);
    EXPECT_NEAR(calcCompliantCapacity(pinch, Eigen::Vector3d::Zero(), torque({0, 0, 1}), options).onset,
                2 * k * d * options.slipDistance, 1e-12);
    options.slipPoints_G = {Eigen::Vector3d(0, 2 * d, 0.01)};
    EXPECT_NEAR(calcCompliantCapacity(pinch, Eigen::Vector3d::Zero(), torque({0, 0, 1}), options).onset,
                k * d * options.slipDistance, 1e-12);
    // On the axis the slip never comes: the onset is the ultimate, both contacts at their cones.
    options.slipPoints_G = {Eigen::Vector3d(0, 0, 0.03)};
    const CompliantCapacity onAxis = calcCompliantCapacity(pinch, Eigen::Vector3d::Zero(), torque({0, 0, 1}), options);
    EXPECT_NEAR(onAxis.ultimate, 2 * options.mu * N * d, 1e-12);
    EXPECT_EQ(onAxis.onset, onAxis.ultimate);
}

TEST(CompliantGraspCapacity, RejectsBadInput) {
    auto pinch = makePinch(5, 4000, 4000, 0, 0);
    CompliantCapacityOptions options;
    EXPECT_THROW(calcCompliantCapacity(pinch, Eigen::Vector3d::Zero(), force({0, 2, 0}), options), InputError);
    Vector6 both = force({0, 1, 0});
    both[0] = 1;
    EXPECT_THROW(calcCompliantCapacity(pinch, Eigen::Vector3d::Zero(), both, options), InputError);
    pinch[1].normalStiffness = 0;
    EXPECT_THROW(calcCompliantCapacity(pinch, Eigen::Vector3d::Zero(), force({0, 1, 0}), options), InputError);
    // A rigid finger with a rigid tangent has no sticking stiffness (singular compliance).
    CompliantContact rigid = makeContact({0, 0, 0}, {1, 0, 0}, 5, 4000, 0);
    rigid.tangentialStiffness = std::numeric_limits<double>::infinity();
    EXPECT_THROW(calcStickingStiffness(rigid), InputError);
    options.kineticMu = options.mu + 0.1;  // kinetic friction above static
    EXPECT_THROW(calcCompliantCapacity(makePinch(5, 4000, 4000, 0, 0), Eigen::Vector3d::Zero(), force({0, 1, 0}), options), InputError);
}

// A ring about y (contacts at +-x pressing with N_a, at +-z with N_b, rigid fingers) loaded along
// -y, tangent at every contact, so all four slip alike. Hertz-Mindlin's equal springs share the
// load equally and the weak pair reaches its cone at 4 mu N_a; full contact's creep (its friction
// ratio a function of the slip alone) brings all four to the cone together, at mu (2 N_a + 2 N_b):
// the creep ramp of the regularized law (compliant_grasp_creep.h, a second method) and the
// springs shared by normal force, whose total is kept, both give that.
TEST(CompliantGraspCapacity, TangentialStiffnessByNormalForceSlipsAsCreep) {
    const double mu = 0.9, Na = 1, Nb = 4, R = 0.04;
    std::vector<CompliantContact> ring;
    for (const auto& [p, N] : {std::pair{Eigen::Vector3d(R, 0, 0), Na}, {Eigen::Vector3d(-R, 0, 0), Na},
                               {Eigen::Vector3d(0, 0, R), Nb}, {Eigen::Vector3d(0, 0, -R), Nb}}) {
        ring.push_back(makeContact(p, -p, N, 4000, 0));
    }
    CompliantCapacityOptions options;
    options.mu = mu;
    options.slipDistance = 1;
    EXPECT_NEAR(calcCompliantCapacity(ring, Eigen::Vector3d::Zero(), force({0, -1, 0}), options).firstSlip, 4 * mu * Na, 1e-9);
    std::vector<CompliantContact> shared = ring;
    setTangentialStiffnessByNormalForce(shared);
    double before = 0, after = 0;
    for (std::size_t i = 0; i < ring.size(); ++i) {
        before += ring[i].tangentialStiffness, after += shared[i].tangentialStiffness;
        EXPECT_NEAR(shared[i].tangentialStiffness / shared[i].force_G.norm(), shared[0].tangentialStiffness / shared[0].force_G.norm(), 1e-9);
    }
    EXPECT_NEAR(after, before, 1e-9 * before);
    const CompliantCapacity c = calcCompliantCapacity(shared, Eigen::Vector3d::Zero(), force({0, -1, 0}), options);
    EXPECT_NEAR(c.firstSlip, mu * 2 * (Na + Nb), 1e-9);
    EXPECT_NEAR(c.ultimate, mu * 2 * (Na + Nb), 1e-9);
    // The creep ramp: the regularizing springs stiff (100 k_n) and equal, friction mu_s = mu_d.
    for (CompliantContact& contact : ring) contact.tangentialStiffness = 100 * contact.normalStiffness;
    contact::ContactParameters friction;
    friction.staticFriction = friction.dynamicFriction = mu;
    friction.transitionVelocity = 1e-3;
    CompliantRampOptions ramp;
    ramp.rate = 6;
    ramp.maxLoad = 20;
    ramp.timeStep = 1e-4;
    const CompliantRamp creep = runCompliantRamp(ring, Eigen::Vector3d::Zero(), force({0, -1, 0}), friction, ramp);
    EXPECT_NEAR(creep.capacity.firstSlip, mu * 2 * (Na + Nb), 0.01 * mu * 2 * (Na + Nb));
}

// A pinch loaded in its tangent plane by a force that combines y and z: the two contacts' cones
// bound the total friction force, 2 mu N in any tangential direction (Coulomb), so the load
// (0, 1, 1) N goes at 2 mu N / sqrt(2) of it, while along y alone and along z alone each goes at
// 2 mu N: per-axis limits would hold it up to 2 mu N of each part, sqrt(2) times as much.
TEST(CompliantGraspCapacity, AlongAWrenchThatCombinesAxesSharesTheCones) {
    const double mu = 0.6, N = 5;
    CompliantCapacityOptions options;
    options.mu = mu;
    options.slipDistance = 1;  // onset = ultimate
    const auto pinch = makePinch(N, 4000, 4000, 3e-4, 3e-4);
    const CompliantCapacity oblique = calcCompliantCapacityAlong(pinch, Eigen::Vector3d::Zero(), force({0, 1, 1}), options);
    EXPECT_NEAR(oblique.ultimate, 2 * mu * N / std::sqrt(2.0), 1e-9);
    EXPECT_NEAR(oblique.onset, oblique.ultimate, 1e-12);
    for (const Eigen::Vector3d& e : {Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, 1)}) {
        EXPECT_NEAR(calcCompliantCapacity(pinch, Eigen::Vector3d::Zero(), force(e), options).ultimate, 2 * mu * N, 1e-9);
    }
    // A unit direction gives the one-axis function's figure.
    const Eigen::Vector3d unit = Eigen::Vector3d(0, 1, 1).normalized();
    EXPECT_NEAR(calcCompliantCapacityAlong(pinch, Eigen::Vector3d::Zero(), force(unit), options).ultimate,
                calcCompliantCapacity(pinch, Eigen::Vector3d::Zero(), force(unit), options).ultimate, 1e-12);
}

// A force F0 along y with a moment T0 about z on a pinch whose contacts sit at x = -d and +d:
// statics gives the contacts' y forces (F0 - T0/d)/2 and (F0 + T0/d)/2 per unit of load, so the
// one at +d reaches mu N at s = 2 mu N / (F0 + T0/d); the one left can turn the object about its
// point (no torsional friction): that is the ultimate.
TEST(CompliantGraspCapacity, AlongAForceWithAMomentReachesTheLoadedContactsCone) {
    const double mu = 0.6, N = 5, d = 0.02, F0 = 1, T0 = 0.01;
    CompliantCapacityOptions options;
    options.mu = mu;
    options.slipDistance = 1;
    Vector6 load = force({0, F0, 0});
    load[2] = T0;
    const CompliantCapacity c =
        calcCompliantCapacityAlong(makePinch(N, 4000, 4000, 3e-4, 3e-4), Eigen::Vector3d::Zero(), load, options);
    EXPECT_NEAR(c.firstSlip, 2 * mu * N / (F0 + T0 / d), 1e-9);
    EXPECT_NEAR(c.ultimate, c.firstSlip, 1e-9);
    EXPECT_THROW(calcCompliantCapacityAlong(makePinch(N, 4000, 4000, 0, 0), Eigen::Vector3d::Zero(), Vector6::Zero(), options),
                 InputError);
}

}  // namespace
}  // namespace graspsim::grasp
