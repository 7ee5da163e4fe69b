// Rigid contact set: a box resting on a box (a pair RigidContact alone rejects) through corner
// contacts, with the reports' forces. Oracles: the weight (normal forces at rest sum to m g)
// and the Coulomb limit of a pulled box (stuck below mu m g, a = (F - mu m g) / m above).
// Frames: Ground G, y up.

#include "graspsim/contact/rigid_contact_set.h"

#include <gtest/gtest.h>
#include <simbody/Simbody.h>

#include <cmath>
#include <cstdio>

#include "graspsim/system/silenced_stdout.h"

namespace graspsim::contact {
namespace {

using SimTK::Transform;
using SimTK::Vec3;

constexpr double kMass = 0.3;  // kg
constexpr double kMu = 0.5;
constexpr double kG = 9.81;
const Vec3 kHalf(0.03, 0.01, 0.02);  // m, the resting box
const Vec3 kTableHalf(0.2, 0.05, 0.2);  // m, the table box, top face at y = 0

struct BoxOnTable {
    SimTK::MultibodySystem system;
    SimTK::SimbodyMatterSubsystem matter{system};
    SimTK::GeneralForceSubsystem forces{system};
    SimTK::MobilizedBody::Free box;
    RigidContactSet contacts;

    explicit BoxOnTable(double pull) {
        SimTK::Force::Gravity(forces, matter, -SimTK::YAxis, kG);
        box = SimTK::MobilizedBody::Free(
            matter.updGround(),
            SimTK::Body::Rigid(SimTK::MassProperties(kMass, Vec3(0), SimTK::UnitInertia::brick(kHalf))));
        SimTK::Force::ConstantForce(forces, box, Vec3(0), Vec3(pull, 0, 0));
        ContactPair pair;
        pair.a = {matter.updGround(), "ground", "table", ContactShape::box(kTableHalf),
                  Transform(Vec3(0, -kTableHalf[1], 0))};
        pair.b = {box, "box", "box", ContactShape::box(kHalf), Transform()};
        pair.parameters.staticFriction = pair.parameters.dynamicFriction = kMu;
        contacts = RigidContactSet(matter, {pair});
        system.realizeTopology();
    }
};

struct Rest {
    double x = 0, vx = 0, normal = 0, friction = 0;
    int touching = 0;
};

Rest run(double pull, double duration) {
    BoxOnTable scene(pull);
    SimTK::State state = scene.system.getDefaultState();
    scene.box.setQToFitTranslation(state, Vec3(0, kHalf[1] + 1e-4, 0));
    SimTK::SemiExplicitEulerTimeStepper stepper(scene.system);
    stepper.setImpulseSolverType(SimTK::SemiExplicitEulerTimeStepper::PGS);
    stepper.setConstraintTolerance(1e-4);
    stepper.initialize(state);
    const double h = 1e-3;
    {
        system::SilencedStdout quiet;
        for (long k = 1; k <= std::lround(duration / h); ++k) stepper.stepTo(k * h);
    }
    const SimTK::State& s = stepper.getState();
    Rest r;
    r.x = scene.box.getBodyOriginLocation(s)[0];
    r.vx = scene.box.getBodyOriginVelocity(s)[0];
    for (const ContactReport& c : scene.contacts.findContactReports(s)) {
        r.normal += c.normalForce * c.n_G[1];
        r.friction += c.frictionForce_G[0];
        if (c.normalForce > 0) ++r.touching;
    }
    return r;
}

TEST(RigidContactSet, BoxBoxBecomesSixteenCornerContacts) {
    BoxOnTable scene(0);
    EXPECT_EQ(scene.contacts.getNumContacts(), 16);
    EXPECT_EQ(scene.contacts.getPairIndex(15), 0);
}

TEST(RigidContactSet, BoxRestsOnItsFourBottomCornersWithItsWeight) {
    const Rest r = run(0, 0.3);
    std::printf("at rest: normal %.5f N (weight %.5f N) on %d corners, |v| %.3g m/s\n", r.normal, kMass * kG,
                r.touching, r.vx);
    EXPECT_NEAR(r.normal, kMass * kG, 0.01 * kMass * kG);
    EXPECT_EQ(r.touching, 4);
    EXPECT_LT(std::abs(r.vx), 1e-4);
}

TEST(RigidContactSet, PulledBoxFollowsCoulomb) {
    const double limit = kMu * kMass * kG;
    const Rest stuck = run(0.5 * limit, 0.3);
    EXPECT_LT(std::abs(stuck.x), 1e-5);
    EXPECT_NEAR(stuck.friction, -0.5 * limit, 0.01 * limit);
    const double duration = 0.2;
    const Rest sliding = run(2 * limit, duration);
    const double a = limit / kMass;  // (2 limit - limit) / m
    std::printf("sliding: a = %.4f m/s^2 from speed, expected %.4f\n", sliding.vx / duration, a);
    EXPECT_NEAR(sliding.vx / duration, a, 0.05 * a);
    EXPECT_NEAR(sliding.friction, -limit, 0.01 * limit);
}

// A palm box against a cylinder, ellipsoid or mesh becomes its 8 corner spheres against the
// object (each a pair RigidContact takes); an object solid on a half-space stays one pair, which
// RigidContact then rejects with its reason.
TEST(RigidContactSet, PalmAgainstObjectSolidsBecomesCornerPairs) {
    SimTK::MultibodySystem system;
    SimTK::SimbodyMatterSubsystem matter(system);
    ContactPair pair;
    pair.a = {matter.updGround(), "hand", "palm", ContactShape::box(Vec3(0.04, 0.05, 0.01)), Transform()};
    for (const ContactShape& object :
         {ContactShape::cylinder(0.03, 0.1), ContactShape::ellipsoid(Vec3(0.04, 0.03, 0.02))}) {
        pair.b = {matter.updGround(), "object", "object", object, Transform()};
        const std::vector<ContactPair> corners = makeRigidContactPairs(pair);
        ASSERT_EQ(corners.size(), 8u);
        for (const ContactPair& c : corners) {
            EXPECT_EQ(c.a.shape.type, ContactShape::Type::Sphere);
            EXPECT_TRUE(isRigidContactSupported(c.a.shape, c.b.shape));
        }
    }
    pair.a.shape = ContactShape::halfSpace();
    EXPECT_EQ(makeRigidContactPairs(pair).size(), 1u);
    EXPECT_FALSE(isRigidContactSupported(pair.a.shape, pair.b.shape));
}

}  // namespace
}  // namespace graspsim::contact
