// The contact force Jacobians against a second method, central finite differences of the force
// law itself, and integrated: a frictionless, undamped ball dropped on a floor and stepped by the
// linearly implicit stepper (ROS2, fixed 1 ms and 0.25 ms steps) bounces without gaining energy
// (measured: it loses 35 % and 1.1 % of the drop energy, an L-stable method's damping of the
// unresolved contact).

#include "graspsim/contact/compliant_contact_jacobian.h"

#include "contact_scenes.h"
#include "graspsim/integration/linearly_implicit_stepper.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace graspsim::contact {
namespace {

using SimTK::Vec3;

ContactParameters makeParameters(double staticFriction, double dynamicFriction) {
    ContactParameters p;
    p.effectiveStiffness = 1e6;
    p.dissipation = 2;
    p.staticFriction = staticFriction;
    p.dynamicFriction = dynamicFriction;
    p.viscousFriction = 0.1;
    p.transitionVelocity = 1e-3;
    return p;
}

// The force on b, F = f_n n + f_t, for relative velocity v at fixed depth (the force law only).
Vec3 calcForce(const ContactParameters& p, const SimTK::UnitVec3& n, double depth, const Vec3& v) {
    const double fn = calcNormalForce(p, 0.01, depth, -SimTK::dot(v, n));
    return fn * n.asVec3() + calcFrictionForce(p, fn, v - SimTK::dot(v, n) * n);
}

ContactReport makeReport(const ContactParameters& p, const SimTK::UnitVec3& n, double depth, const Vec3& v) {
    ContactReport r;
    r.n_G = n;
    r.depth = depth;
    r.depthRate = -SimTK::dot(v, n);
    r.slipVelocity_G = v - SimTK::dot(v, n) * n;
    r.normalForce = calcNormalForce(p, 0.01, depth, r.depthRate);
    return r;
}

void expectMatchesFiniteDifferences(const ContactParameters& p, const Vec3& v) {
    const SimTK::UnitVec3 n(0.3, 1, -0.2);
    const double depth = 2e-4;
    const ContactForceDerivatives d = calcContactForceDerivatives(p, makeReport(p, n, depth, v), true);
    const double dv = 1e-9;
    for (int c = 0; c < 3; ++c) {
        Vec3 e(0);
        e[c] = dv;
        const Vec3 fd = (calcForce(p, n, depth, v + e) - calcForce(p, n, depth, v - e)) / (2 * dv);
        for (int r = 0; r < 3; ++r) EXPECT_NEAR(d.dF_dv(r, c), fd[r], 1e-5 * (1 + std::abs(fd[r]))) << r << "," << c;
    }
    const double dx = 1e-10;  // depth grows as b moves against n
    const Vec3 fdDepth = (calcForce(p, n, depth + dx, v) - calcForce(p, n, depth - dx, v)) / (2 * dx);
    const Vec3 analytic = -(d.dF_dp * n.asVec3());
    for (int r = 0; r < 3; ++r) EXPECT_NEAR(analytic[r], fdDepth[r], 1e-5 * (1 + std::abs(fdDepth[r]))) << r;
}

TEST(CompliantContactJacobian, MatchesFiniteDifferencesBelowTransition) {
    // Slip 0.5 mm/s (half the transition velocity) while approaching at 2 mm/s.
    const SimTK::UnitVec3 n(0.3, 1, -0.2);
    const Vec3 slip = SimTK::UnitVec3(Vec3(1, 0, 0) - Vec3(1, 0, 0).elementwiseMultiply(n.asVec3()).sum() * n).asVec3() * 5e-4;
    expectMatchesFiniteDifferences(makeParameters(0.9, 0.7), slip - 2e-3 * n.asVec3());
}

TEST(CompliantContactJacobian, MatchesFiniteDifferencesWhileSliding) {
    // Slip 5 mm/s, beyond the transition, with mu_s = mu_d (no falling branch to clamp).
    const SimTK::UnitVec3 n(0.3, 1, -0.2);
    const Vec3 t = SimTK::UnitVec3(SimTK::cross(n.asVec3(), Vec3(0, 0, 1))).asVec3();
    expectMatchesFiniteDifferences(makeParameters(0.8, 0.8), 5e-3 * t + 1e-3 * n.asVec3());
}

// The element's generalized forces (one per mobility) at `s`.
SimTK::Vector calcElementForce(const test::Scene& scene, const CompliantContactForce& force, const SimTK::State& s) {
    scene.system.realize(s, SimTK::Stage::Velocity);
    SimTK::Vector_<SimTK::SpatialVec> bodyForces(scene.matter.getNumBodies(), SimTK::SpatialVec(Vec3(0), Vec3(0)));
    SimTK::Vector_<Vec3> particles;
    SimTK::Vector mobility(s.getNU(), 0.0), f;
    force.calcForceContribution(s, bodyForces, particles, mobility);
    scene.matter.multiplyBySystemJacobianTranspose(s, bodyForces, f);
    return f + mobility;
}

// A 200 g ball of radius 45 mm pressed 0.2 mm into a floor, sinking, spinning and sliding at
// `slip` (m/s) along x (the spin about the normal adds none): the element's generalized force f(u)
// and the scene for its Jacobians. mu_s = mu_d, so no falling Stribeck branch is clamped.
struct PressedBall {
    test::Scene scene;
    SimTK::MobilizedBody::Free ball;
    CompliantContactForce force;
    SimTK::State state;

    explicit PressedBall(double slip, double transitionVelocity = 1e-3)
        : ball(scene.addFree(0.2, 0.045)),
          force(scene.forces, {{test::makeSurface(ball, "ball", ContactShape::sphere(0.045)), scene.makeFloor(),
                                test::makeParameters(1e6, 2, 0.8, 0.8, transitionVelocity)}}) {
        state = scene.system.realizeTopology();
        scene.system.realizeModel(state);
        ball.setQToFitTransform(state, SimTK::Transform(SimTK::Rotation(0.3, SimTK::ZAxis), Vec3(0, 0.045 - 2e-4, 0)));
        ball.setUToFitAngularVelocity(state, Vec3(0, -1, 2));
        ball.setUToFitLinearVelocity(state, Vec3(slip - 2 * 0.045, -3e-3, 0));  // rolling about z moves the point by 2 * 0.045
    }

    SimTK::Vector calcGeneralizedForce(const SimTK::State& s) const { return calcElementForce(scene, force, s); }
};

// D = J^T (dF/dv) J against central differences of the element's generalized force in each speed.
template <class Scene>
void expectDampingMatchesFiniteDifferences(Scene& b, const std::string& what) {
    b.scene.system.realize(b.state, SimTK::Stage::Dynamics);
    const CompliantContactJacobian jacobian(b.scene.matter, b.force);
    const int nu = b.state.getNU();
    SimTK::Matrix D(nu, nu, 0.0), K(nu, nu, 0.0);
    jacobian.addForceJacobians(b.state, D, K);
    const double du = 1e-8;
    double largest = 0;
    for (int c = 0; c < nu; ++c) {
        SimTK::State plus = b.state, minus = b.state;
        plus.updU()[c] += du;
        minus.updU()[c] -= du;
        const SimTK::Vector fd = (b.calcGeneralizedForce(plus) - b.calcGeneralizedForce(minus)) / (2 * du);
        for (int r = 0; r < nu; ++r) {
            largest = std::max(largest, std::abs(fd[r]));
            EXPECT_NEAR(D(r, c), fd[r], 1e-5 * (1 + std::abs(fd[r]))) << what << " D(" << r << "," << c << ")";
        }
    }
    EXPECT_GT(largest, 0.1) << what;  // the contact's damping is in there
}

// A two-link finger (pins about z, 40 mm and 30 mm) whose 10 mm tip sphere presses 0.2 mm into
// the floor while its joints turn slowly: the relative Jacobian walks both pins' hinge columns.
struct PressedFinger {
    test::Scene scene;
    SimTK::MobilizedBody::Pin proximal, distal;
    CompliantContactForce force;
    SimTK::State state;

    PressedFinger()
        : proximal(scene.matter.updGround(), SimTK::Transform(Vec3(0, 0.05, 0)), test::Scene::makeBody(0.02, 0.01),
                   SimTK::Transform()),
          distal(proximal, SimTK::Transform(Vec3(0.04, 0, 0)), test::Scene::makeBody(0.02, 0.01), SimTK::Transform()),
          force(scene.forces, {{{distal, "tip", "tip_shape", ContactShape::sphere(0.01), SimTK::Transform(Vec3(0.03, 0, 0))},
                                scene.makeFloor(), test::makeParameters(1e6, 2, 0.8, 0.8, 1e-3)}}) {
        state = scene.system.realizeTopology();
        scene.system.realizeModel(state);
        // Tip centre at 0.05 - 0.04 sin(a) - 0.03 sin(a + b) = 0.01 - 2e-4 with the distal pin straight.
        const double angle = std::asin((0.05 - 0.01 + 2e-4) / 0.07);
        proximal.setOneQ(state, 0, -angle);
        distal.setOneQ(state, 0, 0);
        proximal.setOneU(state, 0, 3e-3);  // the tip slips about 0.2 mm/s: it sticks
        distal.setOneU(state, 0, -2e-3);
    }

    SimTK::Vector calcGeneralizedForce(const SimTK::State& s) const { return calcElementForce(scene, force, s); }
};

// The damping assembled from the contact points the force evaluation cached, on a free ball at a
// point that sticks and at one that slides, and on a finger chain.
TEST(CompliantContactJacobian, AssembledDampingMatchesFiniteDifferencesOfGeneralizedForce) {
    for (double slip : {-4e-4, 6e-3}) {
        PressedBall b(slip);
        expectDampingMatchesFiniteDifferences(b, "ball slipping at " + std::to_string(slip));
    }
    PressedFinger finger;
    expectDampingMatchesFiniteDifferences(finger, "finger");
}

// The contact points the Jacobian reads are the force evaluation's own: equal to a fresh
// geometry pass (findContactReports), whether a Dynamics realization cached them or, realized only
// to Velocity, they are computed on demand.
TEST(CompliantContactJacobian, EvaluatedContactsEqualAFreshGeometryPass) {
    for (SimTK::Stage stage : {SimTK::Stage::Velocity, SimTK::Stage::Dynamics}) {
        PressedBall b(6e-3);
        b.scene.system.realize(b.state, stage);
        const std::vector<ContactReport> fresh = b.force.findContactReports(b.state);
        const std::vector<ContactReport>& cached = b.force.getEvaluatedContacts(b.state);
        ASSERT_EQ(cached.size(), fresh.size());
        ASSERT_EQ(fresh.size(), 1u);
        EXPECT_EQ(cached[0].pairIndex, fresh[0].pairIndex);
        EXPECT_EQ((cached[0].p_G - fresh[0].p_G).norm(), 0.0);
        EXPECT_EQ(cached[0].depth, fresh[0].depth);
        EXPECT_EQ(cached[0].depthRate, fresh[0].depthRate);
        EXPECT_EQ(cached[0].normalForce, fresh[0].normalForce);
        EXPECT_EQ((cached[0].frictionForce_G - fresh[0].frictionForce_G).norm(), 0.0);
        EXPECT_EQ((cached[0].slipVelocity_G - fresh[0].slipVelocity_G).norm(), 0.0);
    }
}

// The active set tells a sticking point (slip below the transition velocity) from a sliding one,
// and lists nothing once the ball is lifted off.
TEST(CompliantContactJacobian, ActiveSetTellsStickingFromSliding) {
    const auto activeSet = [](PressedBall& b) {
        b.scene.system.realize(b.state, SimTK::Stage::Dynamics);
        std::vector<int> active;
        CompliantContactJacobian(b.scene.matter, b.force).appendActiveSet(b.state, active);
        return active;
    };
    PressedBall sticking(-4e-4), sliding(6e-3), lifted(0);
    EXPECT_EQ(activeSet(sticking), (std::vector<int>{0, 1}));  // pushing, sticking
    EXPECT_EQ(activeSet(sliding), std::vector<int>{0});         // pushing only: a term dropped
    lifted.ball.setQToFitTranslation(lifted.state, Vec3(0, 0.05, 0));
    EXPECT_TRUE(activeSet(lifted).empty());
}

// A 200 g ball of radius 45 mm dropped 20 mm onto a floor, drifting sideways; no dissipation and
// no friction, so the continuous motion conserves kinetic + gravity + Hertz energy. Stepped by the
// linearly implicit stepper at `h` for 150 ms (it falls in 64 ms and bounces back up).
struct BounceResult {
    double highestGain = -1;  // largest (E - E0) / E_drop over the run
    double lostShare = 0;     // (E0 - E_end) / E_drop
    double lowest = 1, highestAfterContact = -1;  // ball centre heights (m)
};

BounceResult runBounce(double h) {
    constexpr double kMass = 0.2, kRadius = 0.045, kDrop = 0.02, kG = 9.81;
    test::Scene scene;
    SimTK::Force::Gravity gravity(scene.forces, scene.matter, Vec3(0, -kG, 0));
    SimTK::MobilizedBody::Free ball = scene.addFree(kMass, kRadius);
    const ContactParameters m = test::makeParameters(1e6, 0);
    CompliantContactForce force(scene.forces,
                                {{test::makeSurface(ball, "ball", ContactShape::sphere(kRadius)), scene.makeFloor(), m}});
    const CompliantContactJacobian jacobian(scene.matter, force);
    SimTK::State state = scene.system.realizeTopology();
    scene.system.realizeModel(state);
    ball.setQToFitTranslation(state, Vec3(0, kRadius + kDrop, 0));
    ball.setUToFitLinearVelocity(state, Vec3(0.1, 0, 0.05));
    integration::LinearlyImplicitOptions options;
    options.stepSize = h;
    integration::LinearlyImplicitStepper stepper(scene.system, {&jacobian}, options);
    stepper.initialize(state);
    const double e0 = scene.system.calcEnergy(stepper.getState());
    const double drop = kMass * kG * kDrop + 0.5 * kMass * 0.05 * 0.05;  // energy above rest at contact height
    BounceResult r;
    bool touched = false;
    for (int i = 1; i <= 150; ++i) {
        stepper.stepTo(i * 1e-3);
        const SimTK::State& s = stepper.getState();
        r.highestGain = std::max(r.highestGain, (scene.system.calcEnergy(s) - e0) / drop);
        const double height = ball.getBodyOriginLocation(s)[1];
        r.lowest = std::min(r.lowest, height);
        touched = touched || height < kRadius;
        if (touched) r.highestAfterContact = std::max(r.highestAfterContact, height);
    }
    r.lostShare = (e0 - scene.system.calcEnergy(stepper.getState())) / drop;
    return r;
}

TEST(CompliantContactJacobian, UndampedBounceCreatesNoEnergy) {
    constexpr double kRadius = 0.045;
    double previousLoss = 1;
    for (double h : {1e-3, 2.5e-4}) {
        const BounceResult r = runBounce(h);
        RecordProperty("energy_lost_share_at_h_us_" + std::to_string(static_cast<int>(h * 1e6)), std::to_string(r.lostShare));
        EXPECT_LT(r.lowest, kRadius - 1e-4) << h;                   // it hit the floor
        EXPECT_GT(r.highestAfterContact, kRadius + 2e-3) << h;      // and bounced back up
        EXPECT_LT(r.highestGain, 1e-9) << h;                        // never above its start energy
        EXPECT_LT(r.lostShare, previousLoss) << h;                  // the scheme's loss shrinks with h
        previousLoss = r.lostShare;
    }
}

}  // namespace
}  // namespace graspsim::contact
