#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

#include "contact_scenes.h"
#include "test_meshes.h"
#include "graspsim/contact/anchor_friction.h"
#include "graspsim/contact/compliant_contact_force.h"
#include "graspsim/contact/convex_polytope.h"
#include "graspsim/error.h"
#include "graspsim/integration/cvode_integrator.h"
#include "graspsim/integration/simbody_stepper.h"

// The elastic-anchor friction law (anchor_friction.h): its closed-form pieces, then a box on an
// inclined pad integrated in Simbody against Coulomb's law (no creep below the friction angle,
// the Coulomb acceleration above it), and Simbody's integrator against the CVODE reference.

namespace graspsim::contact {
namespace {

using SimTK::Vec3;

constexpr double kG = 9.81;  // m/s^2

std::string toText(double value) {
    std::ostringstream text;
    text << std::setprecision(6) << value;
    return text.str();
}

ContactParameters makeParameters() {
    ContactParameters p;
    p.effectiveStiffness = 0.66e6;
    p.staticFriction = 0.8;
    p.dynamicFriction = 0.6;
    p.transitionVelocity = 1e-3;
    return p;
}

AnchorContact makePairAlongY(double stiffness, double normalForce, const Vec3& slip) {
    AnchorContact pair;
    pair.stiffness = stiffness;
    pair.normalForce = normalForce;
    pair.n_G = SimTK::UnitVec3(0, 1, 0);
    pair.slipVelocity_G = slip;
    return pair;
}

TEST(AnchorFrictionLaw, SticksAsASpringBelowTheStaticLimit) {
    // k = 1000 N/m, z = 1 mm along x: spring force 1 N < mu_s N = 1.6 N, at rest.
    const AnchorFriction f =
        calcAnchorFriction(makeParameters(), {}, makePairAlongY(1000, 2, Vec3(0)), {Vec3(1e-3, 0, 0), 0.0});
    EXPECT_NEAR(f.force_G[0], -1.0, 1e-12);
    EXPECT_NEAR(f.rate.deflection_G.norm(), 0, 1e-15);  // anchor fixed: no creep
    EXPECT_EQ(f.rate.sliding, 0.0);                     // and it stays stuck
}

TEST(AnchorFrictionLaw, SlidesAtTheLimitAndTheAnchorFollows) {
    // Slip 1 m/s along x, sigma = 1: limit mu_d N = 1.2 N.
    const ContactParameters p = makeParameters();
    const Vec3 z(5e-3, 0, 0);  // spring alone 5 N > limit
    const AnchorFriction f = calcAnchorFriction(p, {}, makePairAlongY(1000, 2, Vec3(1, 0, 0)), {z, 1.0});
    const double limit = 0.6 * 2;
    EXPECT_NEAR(f.force_G.norm(), limit, 1e-12);
    EXPECT_LT(f.force_G[0], 0);
    // dz/dt = v - (1 - F / (k |z|)) z / tau
    EXPECT_NEAR(f.rate.deflection_G[0], 1 - (1 - limit / 5) * 5e-3 / 1e-3, 1e-12);
    EXPECT_NEAR(f.rate.sliding, 0, 1e-15);  // stays sliding
    // From stuck (sigma = 0) the limit is mu_s N = 1.6 N, and sigma rises at 1 / tau.
    const AnchorFriction breaking = calcAnchorFriction(p, {}, makePairAlongY(1000, 2, Vec3(1, 0, 0)), {z, 0.0});
    EXPECT_NEAR(breaking.force_G.norm(), 1.6, 1e-12);
    EXPECT_NEAR(breaking.rate.sliding, 1e3, 1e-9);
}

TEST(AnchorFrictionLaw, NormalDeflectionAndLostContactRelax) {
    const AnchorFriction f =
        calcAnchorFriction(makeParameters(), {}, makePairAlongY(1000, 2, Vec3(0)), {Vec3(0, 1e-4, 0), 0.5});
    EXPECT_NEAR(f.force_G.norm(), 0, 1e-15);  // the normal part makes no friction
    EXPECT_NEAR(f.rate.deflection_G[1], -1e-4 / 1e-3, 1e-12);
    EXPECT_NEAR(f.rate.sliding, -0.5 / 1e-3, 1e-9);  // unloaded: back to stuck
    const AnchorState away = calcAnchorRelaxationRate({}, {Vec3(2e-3, 0, 0), 1.0});
    EXPECT_NEAR((away.deflection_G - Vec3(-2, 0, 0)).norm(), 0, 1e-12);
    EXPECT_NEAR(away.sliding, -1e3, 1e-9);
}

TEST(AnchorFrictionLaw, MindlinStiffnessIsTwoThirdsOfTheNormalStiffness) {
    // k_n = dF_H/dx; with F_H = (4/3) E* sqrt(R) x^(3/2), k_n = 2 E* sqrt(R x).
    const ContactParameters p = makeParameters();
    const double R = 0.01, x = 8e-4, h = 1e-9;
    const double kn = (calcHertzForce(p, R, x + h) - calcHertzForce(p, R, x - h)) / (2 * h);
    EXPECT_NEAR(calcAnchorStiffness(p, {}, R, x), kn * 2.0 / 3.0, 1e-6 * kn);
}

TEST(AnchorFrictionLaw, ParametersAreValidatedWithTheFieldNamed) {
    AnchorFrictionParameters bad;
    bad.dampingMass = -1;
    try {
        bad.validate("scenario contact");
        FAIL() << "accepted a negative damping mass";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "scenario contact: anchor damping mass (-1) must be finite and > 0 (kg)");
    }
    bad = {};
    bad.relaxationTime = std::nan("");
    EXPECT_THROW(bad.validate("x"), InputError);
    EXPECT_THROW(parseFrictionModel("lugre", "--friction"), InputError);
    EXPECT_EQ(parseFrictionModel("anchor", "--friction"), FrictionModel::Anchor);
}

// A 200 g box (60 x 20 x 40 mm) resting on four corners on a pad tilted by `angle` (rad). The
// pad is the floor y = 0 and gravity is tilted instead, so that "downhill" is Ground +x.
struct BoxOnIncline {
    static constexpr double kMass = 0.2, kEStar = 0.66e6;
    static constexpr double kMuS = 0.8, kMuD = 0.6, kTransition = 1e-3;
    const Vec3 halfLengths{0.03, 0.01, 0.02};
    test::Scene scene;
    SimTK::Force::Gravity gravity;
    SimTK::MobilizedBody::Free box;
    CompliantContactForce force;
    SimTK::State state;

    // Anchor springs critically damped on the box's mass (it slides on a fixed pad).
    BoxOnIncline(double angle, FrictionModel model, double initialSpeed = 0)
        : gravity(scene.forces, scene.matter, kG * Vec3(std::sin(angle), -std::cos(angle), 0)),
          box(scene.addFree(kMass, 0.03)) {
        const ContactParameters m = test::makeParameters(kEStar, 1.0, kMuS, kMuD, kTransition);
        FrictionSettings friction;
        friction.model = model;
        friction.anchor.dampingMass = kMass;
        force = CompliantContactForce(
            scene.forces, {{scene.makeFloor(), test::makeSurface(box, "box", ContactShape::box(halfLengths)), m}},
            friction);
        state = scene.system.realizeTopology();
        // Rest on the static Hertz depth of a corner carrying a quarter of the normal load.
        const double depth =
            test::calcStaticHertzDepth(kMass * kG * std::cos(angle) / 4, kEStar, kDefaultBoxCornerRadius);
        box.setQToFitTranslation(state, Vec3(0, halfLengths[1] - depth, 0));
        box.setUToFitLinearVelocity(state, Vec3(initialSpeed, 0, 0));
    }
    // Mindlin stiffness (N/m) of one corner at the static depth (anchor_friction.h).
    static double calcCornerStiffness(double angle) {
        const double depth =
            test::calcStaticHertzDepth(kMass * kG * std::cos(angle) / 4, kEStar, kDefaultBoxCornerRadius);
        ContactParameters p;
        p.effectiveStiffness = kEStar;
        return calcAnchorStiffness(p, {}, kDefaultBoxCornerRadius, depth);
    }
    double getDownhill(const SimTK::State& s) const { return box.getBodyOriginLocation(s)[0]; }
    double getDownhillSpeed(const SimTK::State& s) const { return box.getBodyOriginVelocity(s)[0]; }
};

// Downhill position (m), speed (m/s) and the anchor's downhill deflection (m) at a time.
struct Sample {
    double first, second, deflection;
};

// Samples at each time (s), integrated with Runge-Kutta-Merson at 1e-7.
std::vector<Sample> integrate(BoxOnIncline& s, const std::vector<double>& times) {
    SimTK::RungeKuttaMersonIntegrator integrator(s.scene.system);
    integrator.setAccuracy(1e-7);
    SimTK::TimeStepper stepper(s.scene.system, integrator);
    stepper.initialize(s.state);
    std::vector<Sample> samples;
    for (double t : times) {
        stepper.stepTo(t);
        const SimTK::State& now = integrator.getState();
        samples.push_back({s.getDownhill(now), s.getDownhillSpeed(now), s.force.getAnchorDeflection(now, 0)[0]});
    }
    return samples;
}

TEST(AnchorFrictionIncline, BelowTheFrictionAngleTheBoxDoesNotCreep) {
    // 35 deg: tan = 0.70, above mu_d = 0.6 but below mu_s = 0.8 (friction angle 38.7 deg). Once
    // the anchor springs have taken the load (0.26 mm of deflection in about 30 ms) and the
    // rocking on the four corners has died down, the box must not move on.
    const double angle = 35 * SimTK::Pi / 180;
    BoxOnIncline anchor(angle, FrictionModel::Anchor);
    const auto held = integrate(anchor, {0.5, 1.5});
    const double drift = held[1].first - held[0].first;  // m over 1 s
    RecordProperty("anchor_drift_um_per_s", toText(drift * 1e6));
    RecordProperty("anchor_deflection_um", toText(held[0].first * 1e6));
    EXPECT_LT(std::abs(drift), 5e-8);          // < 0.05 um/s
    EXPECT_LT(std::abs(held[0].first), 1e-3);  // bounded: the springs' deflection, below 1 mm
    // Static springs: k z = m g sin a, with k the four corners' Mindlin stiffness.
    const double load = BoxOnIncline::kMass * kG * std::sin(angle);
    const double deflection = load / (4 * BoxOnIncline::calcCornerStiffness(angle));
    EXPECT_NEAR(held[1].deflection, deflection, 0.02 * deflection);
    // The same box with the regularized law cannot stay: its friction needs slip, and slip beyond
    // v_tr lowers it toward mu_d < tan a, so the box slides away (0.5 m in this second). What
    // the anchor removes, and a check that the scene does load friction beyond mu_d.
    BoxOnIncline regularized(angle, FrictionModel::Regularized);
    const auto creeping = integrate(regularized, {0.2, 1.2});
    RecordProperty("regularized_drift_um_per_s", toText((creeping[1].first - creeping[0].first) * 1e6));
    EXPECT_GT(creeping[1].first - creeping[0].first, 1e-4);
}

TEST(AnchorFrictionIncline, AboveTheFrictionAngleTheBoxSlidesWithCoulombAcceleration) {
    // 45 deg: a = g (sin a - mu_d cos a) = 2.775 m/s^2 once slip is far above v_tr.
    const double angle = 45 * SimTK::Pi / 180;
    BoxOnIncline s(angle, FrictionModel::Anchor);
    const auto samples = integrate(s, {0.1, 0.3});
    const double a = (samples[1].second - samples[0].second) / 0.2;
    const double coulomb = kG * (std::sin(angle) - BoxOnIncline::kMuD * std::cos(angle));
    RecordProperty("acceleration", toText(a));
    EXPECT_NEAR(a, coulomb, 0.02 * coulomb);
}

TEST(AnchorFrictionIncline, AnchorRelaxesWhenTheBoxLeavesThePadAndWhenThePairIsDisabled) {
    // Held at 35 deg with its springs loaded (0.24 mm), the box is thrown off the pad at 1 m/s
    // (about 0.2 s of flight): with no contact the anchor returns to the current point in tau =
    // 1 ms, so 50 ms later nothing is left of it (e^-50; we allow the integrator's error, 1e-4 of
    // the load), and the integrator never sees a jump.
    const double angle = 35 * SimTK::Pi / 180;
    BoxOnIncline s(angle, FrictionModel::Anchor);
    SimTK::RungeKuttaMersonIntegrator integrator(s.scene.system);
    integrator.setAccuracy(1e-7);
    SimTK::TimeStepper stepper(s.scene.system, integrator);
    stepper.initialize(s.state);
    stepper.stepTo(0.3);
    SimTK::State thrown = integrator.getState();
    const double loaded = s.force.getAnchorDeflection(thrown, 0).norm();
    EXPECT_GT(loaded, 1e-4);
    SimTK::State disabled = thrown;
    s.box.setUToFitLinearVelocity(thrown, Vec3(0, 1, 0));
    stepper.initialize(thrown);
    stepper.stepTo(0.35);
    EXPECT_GT(s.box.getBodyOriginLocation(integrator.getState())[1], s.halfLengths[1]);  // in flight
    EXPECT_LT(s.force.getAnchorDeflection(integrator.getState(), 0).norm(), 1e-4 * loaded);
    // The same from the loaded state with the pair switched off instead (the engaged approximation).
    s.force.setPairEnabled(disabled, 0, false);
    stepper.initialize(disabled);
    stepper.stepTo(0.35);
    EXPECT_LT(s.force.getAnchorDeflection(integrator.getState(), 0).norm(), 1e-4 * loaded);
}

// Downhill position and speed and the anchor's deflection at `time` with integrator `stepper`.
struct RunEnd {
    double position, speed;
    Vec3 deflection;
};

RunEnd runToEnd(BoxOnIncline& s, integration::Stepper& stepper, double time) {
    stepper.initialize(s.state);
    stepper.stepTo(time);
    const SimTK::State& end = stepper.getState();
    return {s.getDownhill(end), s.getDownhillSpeed(end), s.force.getAnchorDeflection(end, 0)};
}

TEST(AnchorFrictionIncline, SimbodyAndTheCvodeReferenceAgreeThroughSlideAndStick) {
    // 25 deg, launched downhill at 0.2 m/s: it slides, decelerating at g (mu_d cos a - sin a) =
    // 1.19 m/s^2, and sticks after about 0.17 s (tan 25 deg = 0.47 < mu_s). Both integrators at
    // 1e-8 must agree on where it stops and on the anchor state (Z variables in the State).
    const double angle = 25 * SimTK::Pi / 180;
    BoxOnIncline simbodyRun(angle, FrictionModel::Anchor, 0.2);
    integration::SimbodyCpodesStepper simbody(simbodyRun.scene.system, 1e-8);
    const RunEnd a = runToEnd(simbodyRun, simbody, 0.3);

    BoxOnIncline cvodeRun(angle, FrictionModel::Anchor, 0.2);
    integration::CvodeOptions options;
    options.relativeTolerance = 1e-8;
    integration::CvodeIntegrator cvode(cvodeRun.scene.system, options);
    const RunEnd b = runToEnd(cvodeRun, cvode, 0.3);

    RecordProperty("stop_mm", toText(a.position * 1e3));
    RecordProperty("difference_um", toText((a.position - b.position) * 1e6));
    EXPECT_NEAR(a.position, b.position, 1e-7);
    EXPECT_NEAR(a.speed, 0, 1e-5);  // stuck (the last rocking on the corners dying down)
    EXPECT_NEAR(b.speed, 0, 1e-5);
    EXPECT_NEAR((a.deflection - b.deflection).norm(), 0, 1e-8);
    EXPECT_GT(a.deflection.norm(), 1e-6);  // the anchor does carry the load
    // Coulomb stopping distance v0^2 / (2 a) = 16.8 mm, a few per cent less: for the first few
    // ms, while the springs load up, the limit is the static one.
    const double coulomb = 0.2 * 0.2 / (2 * kG * (BoxOnIncline::kMuD * std::cos(angle) - std::sin(angle)));
    EXPECT_LT(a.position, coulomb);
    EXPECT_GT(a.position, 0.9 * coulomb);
}


// A 100 g object pinched through its centre of mass between two 20 g pads on x Sliders, each
// pushed inward with 1 N, under gravity along -y: 2 mu_d N = 1.2 N > m g = 0.98 N, so both laws
// hold it, the regularized one creeping. Every object shape, against sphere pads (one contact
// per pair) and box pads (several contacts per pair, one shared anchor).
struct PinchCase {
    const char* name;
    ContactShape object;
    bool boxPads;
};

struct Pinch {
    static constexpr double kMass = 0.1, kPadMass = 0.02, kPush = 1.0, kHalfWidth = 0.03;
    test::Scene scene;
    SimTK::Force::Gravity gravity{scene.forces, scene.matter, Vec3(0, -kG, 0)};
    SimTK::MobilizedBody::Free object;
    SimTK::MobilizedBody::Slider left, right;
    CompliantContactForce force;
    SimTK::State state;

    Pinch(const PinchCase& c, FrictionModel model)
        : object(scene.addFree(kMass, kHalfWidth)),
          left(scene.addSlider(SimTK::XAxis, kPadMass, 0.01)),
          right(scene.addSlider(SimTK::XAxis, kPadMass, 0.01)) {
        SimTK::Force::MobilityConstantForce(scene.forces, left, 0, kPush);
        SimTK::Force::MobilityConstantForce(scene.forces, right, 0, -kPush);
        const ContactParameters m = test::makeParameters(0.66e6, 1.0, 0.8, 0.6, 1e-3);
        const ContactShape pad = c.boxPads ? ContactShape::box(Vec3(0.005, 0.01, 0.01)) : ContactShape::sphere(0.008);
        FrictionSettings friction;
        friction.model = model;
        force = CompliantContactForce(scene.forces, {{test::makeSurface(left, "left", pad),
                                                      test::makeSurface(object, "object", c.object), m},
                                                     {test::makeSurface(right, "right", pad),
                                                      test::makeSurface(object, "object", c.object), m}},
                                      friction);
        state = scene.system.realizeTopology();
        const double padHalf = c.boxPads ? 0.005 : 0.008;
        left.setOneQ(state, 0, -(kHalfWidth + padHalf));
        right.setOneQ(state, 0, kHalfWidth + padHalf);
    }
};

class AnchorPinch : public ::testing::TestWithParam<PinchCase> {};

// Object height (m) at 0.4 s and 1.2 s.
std::pair<double, double> integratePinch(Pinch& p) {
    SimTK::RungeKuttaMersonIntegrator integrator(p.scene.system);
    integrator.setAccuracy(1e-6);
    SimTK::TimeStepper stepper(p.scene.system, integrator);
    stepper.initialize(p.state);
    stepper.stepTo(0.4);
    const double settled = p.object.getBodyOriginLocation(integrator.getState())[1];
    stepper.stepTo(1.2);
    return {settled, p.object.getBodyOriginLocation(integrator.getState())[1]};
}

TEST_P(AnchorPinch, ObjectHeldWithoutCreep) {
    Pinch anchor(GetParam(), FrictionModel::Anchor);
    const auto [settled, end] = integratePinch(anchor);
    RecordProperty("anchor_drift_um_per_s", toText((end - settled) / 0.8 * 1e6));
    EXPECT_LT(std::abs(end - settled) / 0.8, 1e-7);  // < 0.1 um/s
    EXPECT_LT(std::abs(settled), 2e-3);               // caught within the springs' travel
}

TEST(AnchorPinchContrast, RegularizedLawCreepsInTheSamePinch) {
    // What the anchor removes, and a check that the pinch does load friction: the regularized law
    // creeps near v_tr m g / (2 mu N) = 0.6 mm/s (mu between mu_d and mu_s near v_tr).
    Pinch regularized({"Sphere", ContactShape::sphere(0.03), false}, FrictionModel::Regularized);
    const auto [from, to] = integratePinch(regularized);
    RecordProperty("regularized_drift_um_per_s", toText((to - from) / 0.8 * 1e6));
    EXPECT_LT(to - from, -1e-4 * 0.8);  // creeps down faster than 0.1 mm/s
}

std::shared_ptr<const ConvexPolytope> makeBoxPolytope() {
    return ConvexPolytope::build(test::makeBoxMesh(Vec3(0.03, 0.03, 0.02)), "test box mesh");
}

INSTANTIATE_TEST_SUITE_P(
    EveryShape, AnchorPinch,
    ::testing::Values(PinchCase{"Sphere", ContactShape::sphere(0.03), false},
                      PinchCase{"Box", ContactShape::box(Vec3(0.03, 0.03, 0.02)), false},
                      PinchCase{"Cylinder", ContactShape::cylinder(0.03, 0.06), false},
                      PinchCase{"Capsule", ContactShape::capsule(0.03, 0.04), false},
                      PinchCase{"Ellipsoid", ContactShape::ellipsoid(Vec3(0.03, 0.04, 0.035)), false},
                      PinchCase{"Mesh", ContactShape::convexMesh(makeBoxPolytope()), false},
                      PinchCase{"BoxOnBoxPads", ContactShape::box(Vec3(0.03, 0.03, 0.02)), true},
                      PinchCase{"MeshOnBoxPads", ContactShape::convexMesh(makeBoxPolytope()), true},
                      PinchCase{"CylinderOnBoxPads", ContactShape::cylinder(0.03, 0.06), true}),
    [](const ::testing::TestParamInfo<PinchCase>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace graspsim::contact
