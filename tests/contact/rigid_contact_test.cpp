// Rigid contact (RigidContact over RigidContactConstraint, driven by Simbody's
// SemiExplicitEulerTimeStepper): exact gap geometry, and the analytic squeeze test, a box held
// between two spheres pressed with a known force and pulled tangentially. Frames: Ground G, y up.

#include "graspsim/contact/rigid_contact.h"

#include <gtest/gtest.h>
#include <simbody/Simbody.h>

#include <cmath>
#include <memory>

#include "graspsim/contact/rigid_contact_geometry.h"
#include "graspsim/error.h"

namespace graspsim::contact {
namespace {

using SimTK::Transform;
using SimTK::Vec3;

TEST(RigidContactGeometry, SphereAndBoxGapIsExactApartAndOverlapping) {
    const ContactShape sphere = ContactShape::sphere(0.01);
    const ContactShape box = ContactShape::box(Vec3(0.02, 0.05, 0.03));
    for (double gap : {0.3, 0.004, 1e-7, -1e-4, -0.003}) {
        // sphere on the +x side of the box: normal from sphere (A) toward box (B) is -x
        const Transform X_GA(Vec3(0.02 + 0.01 + gap, 0.01, -0.005));
        const RigidContactGeometry g =
            findRigidContactGeometry(sphere, X_GA, box, Transform(), 0.01);
        EXPECT_NEAR(g.separation, gap, 1e-12) << gap;
        EXPECT_NEAR(g.n_F[0], -1, 1e-12) << gap;
        EXPECT_NEAR(g.p_F[0], 0.02 + gap / 2, 1e-12) << gap;
        EXPECT_NEAR(g.p_F[1], 0.01, 1e-12) << gap;
        // swapped order: same gap and point, normal negated
        const RigidContactGeometry h =
            findRigidContactGeometry(box, Transform(), sphere, X_GA, 0.01);
        EXPECT_NEAR(h.separation, gap, 1e-12) << gap;
        EXPECT_NEAR(h.n_F[0], 1, 1e-12) << gap;
        EXPECT_NEAR((h.p_F - g.p_F).norm(), 0, 1e-12) << gap;
    }
}

TEST(RigidContactGeometry, CapsuleCornerGapIsEuclidean) {
    // capsule axis along z_G, beside the box's (+x, +y) edge, diagonally away from it
    const ContactShape capsule = ContactShape::capsule(0.01, 0.04);
    const ContactShape box = ContactShape::box(Vec3(0.02, 0.05, 0.03));
    const double d = 0.007;  // distance from the edge to the capsule surface
    const Vec3 axisPoint = Vec3(0.02, 0.05, 0) + (0.01 + d) * Vec3(1, 1, 0) / std::sqrt(2.0);
    const RigidContactGeometry g =
        findRigidContactGeometry(box, Transform(), capsule, Transform(axisPoint), 0.001);
    EXPECT_NEAR(g.separation, d, 1e-9);
    EXPECT_NEAR(g.n_F[0], 1 / std::sqrt(2.0), 1e-9);
    EXPECT_NEAR(g.n_F[1], 1 / std::sqrt(2.0), 1e-9);
}

TEST(RigidContactGeometry, RejectsTwoSolids) {
    const ContactShape box = ContactShape::box(Vec3(0.02, 0.05, 0.03));
    EXPECT_FALSE(isRigidContactSupported(box, ContactShape::halfSpace()));
    EXPECT_THROW(findRigidContactGeometry(box, Transform(), box, Transform(Vec3(0.03, 0, 0)), 0.01),
                 InputError);
}

// A box (mass m, Free mobilizer, no gravity) between two spheres on Sliders along x, each
// pressed toward the box with a constant force N; a constant force F along +y pulls the box.
struct SqueezeScene {
    static constexpr double kMu = 0.5;
    static constexpr double kPress = 4.0;    // N, each sphere
    static constexpr double kBoxMass = 0.1;  // kg
    static constexpr double kRadius = 0.01;  // m, spheres
    static constexpr double kHalfX = 0.02;   // m, box half-length along x
    static constexpr double kHalfY = 0.5;    // m, box half-length along y (the pull)
    static constexpr double kStep = 1e-3;    // s

    SimTK::MultibodySystem system;
    SimTK::SimbodyMatterSubsystem matter{system};
    SimTK::GeneralForceSubsystem forces{system};
    SimTK::MobilizedBody::Free box;
    SimTK::MobilizedBody::Slider left, right;
    SimTK::UnilateralContactIndex leftContact, rightContact;

    explicit SqueezeScene(double pull) {
        // Long along the pull (y) so that the spheres stay on the faces while the box slides.
        const Vec3 h(kHalfX, kHalfY, 0.03);
        SimTK::Body::Rigid boxBody(
            SimTK::MassProperties(kBoxMass, Vec3(0), SimTK::UnitInertia::brick(h[0], h[1], h[2])));
        box = SimTK::MobilizedBody::Free(matter.updGround(), boxBody);
        SimTK::Body::Rigid ball(
            SimTK::MassProperties(0.02, Vec3(0), SimTK::UnitInertia::sphere(kRadius)));
        // A Slider translates along x of its frames, here Ground's x: q is the centre's x.
        left = SimTK::MobilizedBody::Slider(matter.updGround(), ball);
        right = SimTK::MobilizedBody::Slider(matter.updGround(), ball);
        SimTK::Force::MobilityConstantForce(forces, left, 0, kPress);
        SimTK::Force::MobilityConstantForce(forces, right, 0, -kPress);
        SimTK::Force::ConstantForce(forces, box, Vec3(0), Vec3(0, pull, 0));

        ContactParameters parameters;
        parameters.staticFriction = kMu;
        parameters.dynamicFriction = kMu;
        const ContactSurface boxSurface{box, "box", "box", ContactShape::box(h), Transform()};
        const ContactSurface leftSurface{left, "left", "ball", ContactShape::sphere(kRadius), Transform()};
        const ContactSurface rightSurface{right, "right", "ball", ContactShape::sphere(kRadius), Transform()};
        // The sphere is A in one pair and B in the other, so both orders are exercised.
        leftContact = RigidContact::add(matter, ContactPair{leftSurface, boxSurface, parameters});
        rightContact = RigidContact::add(matter, ContactPair{boxSurface, rightSurface, parameters});
        system.realizeTopology();
    }

    SimTK::State makeTouchingState() const {
        SimTK::State state = system.getDefaultState();
        left.setOneQ(state, 0, -(kHalfX + kRadius));
        right.setOneQ(state, 0, kHalfX + kRadius);
        system.realize(state, SimTK::Stage::Position);
        return state;
    }

    const RigidContact& contact(SimTK::UnilateralContactIndex i) const {
        return dynamic_cast<const RigidContact&>(matter.getUnilateralContact(i));
    }
};

// isProximal() skips the exact gap search for pairs whose bounding spheres are apart (the box's
// bounding radius is 0.5 m here); its answer must stay that of the exact gap at every distance.
TEST(RigidContact, IsProximalAgreesWithTheExactGap) {
    SqueezeScene scene(0);
    SimTK::State state = scene.makeTouchingState();
    const RigidContact& contact = scene.contact(scene.rightContact);
    const double tolerance = 1e-5;  // m
    for (double gap : {3.0, 0.6, 0.45, 0.01, 2e-5, 1e-5, 5e-6, 0.0, -1e-4}) {
        scene.right.setOneQ(state, 0, SqueezeScene::kHalfX + SqueezeScene::kRadius + gap);
        scene.system.realize(state, SimTK::Stage::Position);
        EXPECT_NEAR(contact.getPerr(state), gap, 1e-12) << gap;
        EXPECT_EQ(contact.isProximal(state, tolerance), contact.getPerr(state) <= tolerance) << gap;
    }
}

struct SqueezeResult {
    double y = 0, vy = 0;                    // box centre height (m) and speed (m/s) at the end
    double maxOffAxis = 0;                   // largest |x|, |z| of the box centre (m)
    double maxAngularSpeed = 0;              // rad/s
    double maxPenetration = 0;               // m, over both contacts
    double normalLeft = 0, normalRight = 0;  // N, last step's normal multipliers, negated
};

SqueezeResult runSqueeze(double pull, double duration,
                         SimTK::SemiExplicitEulerTimeStepper::ImpulseSolverType solver) {
    SqueezeScene scene(pull);
    SimTK::SemiExplicitEulerTimeStepper stepper(scene.system);
    stepper.setImpulseSolverType(solver);
    stepper.initialize(scene.makeTouchingState());
    SqueezeResult r;
    const int steps = static_cast<int>(std::lround(duration / SqueezeScene::kStep));
    for (int i = 1; i <= steps; ++i) {
        stepper.stepTo(i * SqueezeScene::kStep);
        const SimTK::State& s = stepper.getState();
        const Vec3 p = scene.box.getBodyOriginLocation(s);
        r.maxOffAxis = std::max({r.maxOffAxis, std::abs(p[0]), std::abs(p[2])});
        r.maxAngularSpeed = std::max(r.maxAngularSpeed, scene.box.getBodyAngularVelocity(s).norm());
        for (auto ix : {scene.leftContact, scene.rightContact})
            r.maxPenetration = std::max(r.maxPenetration, -scene.contact(ix).getPerr(s));
    }
    // The stepper leaves its state at Stage::Dynamics with the step's multipliers filled in;
    // getMultipliers() would insist on Stage::Acceleration, updMultipliers() does not.
    SimTK::State& s = stepper.updState();
    r.y = scene.box.getBodyOriginLocation(s)[1];
    r.vy = scene.box.getBodyOriginVelocity(s)[1];
    const SimTK::Vector& lambda = s.updMultipliers();
    const SimTK::MultiplierIndex leftIx =
        scene.contact(scene.leftContact).getContactMultiplierIndex(s);
    const SimTK::MultiplierIndex rightIx =
        scene.contact(scene.rightContact).getContactMultiplierIndex(s);
    if (!leftIx.isValid() || !rightIx.isValid()) {
        ADD_FAILURE() << "a contact was released";
        return r;
    }
    r.normalLeft = -lambda[leftIx];
    r.normalRight = -lambda[rightIx];
    return r;
}

// PGS: Simbody 3.7's default PLUS solver holds the box at every pull, friction impulses beyond
// the Coulomb cone included (its impending-slip Newton iteration settles on a zero slip
// direction, which satisfies its equations trivially).
constexpr auto kSolver = SimTK::SemiExplicitEulerTimeStepper::PGS;
constexpr double kFrictionLimit = 2 * SqueezeScene::kMu * SqueezeScene::kPress;  // N

TEST(RigidContactSqueeze, BoxStaysBelowTheFrictionLimit) {
    for (double fraction : {0.0, 0.5, 0.9, 0.98}) {
        const SqueezeResult r = runSqueeze(fraction * kFrictionLimit, 0.3, kSolver);
        // PGS stops iterating at its own tolerance, so a stuck box creeps by micrometres: the
        // bounds are a hundredth of what the weakest sliding case (1.1 x the limit) reaches.
        EXPECT_LT(std::abs(r.y), 1e-5) << fraction;
        EXPECT_LT(std::abs(r.vy), 1e-4) << fraction;
        EXPECT_NEAR(r.normalLeft, SqueezeScene::kPress, 0.01 * SqueezeScene::kPress) << fraction;
        EXPECT_NEAR(r.normalRight, SqueezeScene::kPress, 0.01 * SqueezeScene::kPress) << fraction;
        EXPECT_LT(r.maxOffAxis, 1e-6) << fraction;
        EXPECT_LT(r.maxAngularSpeed, 1e-3) << fraction;
        EXPECT_LT(r.maxPenetration, 1e-4) << fraction;
        std::printf("pull %.3f N (stuck): y = %.3g m, vy = %.3g m/s, |w| max = %.3g rad/s\n",
                    fraction * kFrictionLimit, r.y, r.vy, r.maxAngularSpeed);
    }
}

TEST(RigidContactSqueeze, BoxSlidesWithTheCoulombAcceleration) {
    const double duration = 0.1;  // the fastest case slides 0.4 m, less than kHalfY
    for (double fraction : {1.1, 1.5, 3.0}) {
        const double pull = fraction * kFrictionLimit;
        const double expected = (pull - kFrictionLimit) / SqueezeScene::kBoxMass;  // m/s^2
        const SqueezeResult r = runSqueeze(pull, duration, kSolver);
        const double fromSpeed = r.vy / duration;
        const double fromDistance = 2 * r.y / (duration * duration);
        EXPECT_NEAR(fromSpeed, expected, 0.05 * expected) << fraction;
        EXPECT_NEAR(fromDistance, expected, 0.05 * expected) << fraction;
        EXPECT_NEAR(r.normalLeft, SqueezeScene::kPress, 0.01 * SqueezeScene::kPress) << fraction;
        EXPECT_NEAR(r.normalRight, SqueezeScene::kPress, 0.01 * SqueezeScene::kPress) << fraction;
        EXPECT_LT(r.maxOffAxis, 1e-6) << fraction;
        EXPECT_LT(r.maxAngularSpeed, 1e-6) << fraction;
        EXPECT_LT(r.maxPenetration, 1e-4) << fraction;
        std::printf("pull %.3f N: a = %.6f m/s^2 (speed), %.6f (distance), expected %.6f\n", pull,
                    fromSpeed, fromDistance, expected);
    }
}

TEST(RigidContactDrop, SphereFallsOntoFloorAndComesToRest) {
    // A sphere dropped from 5 cm above a half-space floor (restitution 0): free fall until the
    // gap closes, then rest on the surface. Exercises the distal -> proximal transition.
    SimTK::MultibodySystem system;
    SimTK::SimbodyMatterSubsystem matter(system);
    SimTK::GeneralForceSubsystem forces(system);
    SimTK::Force::Gravity(forces, matter, -SimTK::YAxis, 9.81);
    const double r = 0.02, drop = 0.05;
    SimTK::MobilizedBody::Free ball(
        matter.updGround(),
        SimTK::Body::Rigid(SimTK::MassProperties(0.1, Vec3(0), SimTK::UnitInertia::sphere(r))));
    const ContactSurface ballSurface{ball, "ball", "ball", ContactShape::sphere(r), Transform()};
    const ContactSurface floor{matter.updGround(), "ground", "floor", ContactShape::halfSpace(),
                               Transform(SimTK::Rotation(-SimTK::Pi / 2, SimTK::XAxis), Vec3(0))};
    ContactParameters parameters;
    parameters.staticFriction = parameters.dynamicFriction = 0.5;
    const auto ix = RigidContact::add(matter, ContactPair{ballSurface, floor, parameters});
    system.realizeTopology();
    SimTK::State state = system.getDefaultState();
    ball.setQToFitTranslation(state, Vec3(0, r + drop, 0));
    SimTK::SemiExplicitEulerTimeStepper stepper(system);
    stepper.setImpulseSolverType(kSolver);
    // Contacts closer than this count as touching (proximal) and are held there.
    const double tolerance = 1e-4;  // m
    stepper.setConstraintTolerance(tolerance);
    stepper.initialize(state);
    const auto& contact = dynamic_cast<const RigidContact&>(matter.getUnilateralContact(ix));
    const double h = 1e-3;
    const double fallTime = std::sqrt(2 * drop / 9.81);  // about 0.101 s
    double minGap = drop;
    for (int n = 1; n <= 400; ++n) {
        stepper.stepTo(n * h);
        const SimTK::State& s = stepper.getState();
        minGap = std::min(minGap, contact.getPerr(s));
        if (n * h < fallTime - 2 * h) {  // still falling freely: y = r + drop - g t^2 / 2
            EXPECT_NEAR(ball.getBodyOriginLocation(s)[1], r + drop - 0.5 * 9.81 * n * h * n * h,
                        0.5 * 9.81 * h * n * h + 1e-12)
                << n;
        }
    }
    // The contact is found on the first step that ends inside the floor, so the penetration
    // is at most one step of the impact speed. Simbody 3.7's stepper does not project it out
    // afterwards: its own SpherePlaneContact in this scene rests at the same -0.531 mm.
    const double impactStep = std::sqrt(2 * 9.81 * drop) * h;  // m
    const SimTK::State& s = stepper.getState();
    EXPECT_LE(contact.getPerr(s), tolerance);
    EXPECT_GE(contact.getPerr(s), -impactStep);
    EXPECT_NEAR(contact.getPerr(s), -0.000531272, 1e-8);  // the built-in's resting gap
    EXPECT_GE(minGap, -impactStep);
    EXPECT_LT(ball.getBodyOriginVelocity(s).norm(), 1e-3);
    std::printf("drop: rest gap %.6g m, deepest %.6g m, speed %.3g m/s\n", contact.getPerr(s),
                -minGap, ball.getBodyOriginVelocity(s).norm());
}

TEST(RigidContact, RejectsTwoSolidsAndBadParameters) {
    SimTK::MultibodySystem system;
    SimTK::SimbodyMatterSubsystem matter(system);
    SimTK::Body::Rigid body(SimTK::MassProperties(1, Vec3(0), SimTK::UnitInertia(1)));
    SimTK::MobilizedBody::Free a(matter.updGround(), body);
    SimTK::MobilizedBody::Free b(matter.updGround(), body);
    const ContactShape box = ContactShape::box(Vec3(0.02, 0.05, 0.03));
    const ContactSurface boxA{a, "a", "box", box, Transform()};
    const ContactSurface boxB{b, "b", "box", box, Transform()};
    const ContactSurface ballB{b, "b", "ball", ContactShape::sphere(0.01), Transform()};
    EXPECT_THROW(RigidContact(matter, ContactPair{boxA, boxB}), InputError);
    ContactPair bad{boxA, ballB};
    bad.parameters.staticFriction = 0.2;
    bad.parameters.dynamicFriction = 0.3;
    EXPECT_THROW(RigidContact(matter, bad), InputError);
    RigidContactOptions badOptions;
    badOptions.minRestitution = 1.5;
    EXPECT_THROW(RigidContact(matter, ContactPair{boxA, ballB}, badOptions), InputError);
}

}  // namespace
}  // namespace graspsim::contact
