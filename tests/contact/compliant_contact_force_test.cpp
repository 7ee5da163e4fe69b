#include "graspsim/contact/compliant_contact_force.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "contact_scenes.h"
#include "graspsim/contact/contact_force_law.h"
#include "graspsim/contact/shape_contact.h"
#include "graspsim/error.h"

// Evaluations at one state (no integration): forces of many simultaneous contacts, energy,
// reports, and switching pairs. Integrated physics is in compliant_contact_dynamics_test.cpp.

namespace graspsim::contact {
namespace {

using SimTK::SpatialVec;
using SimTK::Transform;
using SimTK::Vec3;
using test::Scene;

constexpr double kEStar = 1e6;      // Pa
constexpr double kRadius = 0.01;    // m, every sphere
constexpr double kDissipation = 1;  // s/m

// Five spheres on Free bodies pressing into the top face (z = 0.02) of a free plate at
// different depths and speeds. Sphere 0, listed first, separates at 2 m/s: its Hunt-Crossley
// force 1 + 1.5 c xdot = 1 - 3 < 0 is clamped to zero. HuntCrossleyForce would return at that
// contact and drop the four after it.
struct FiveSpheresOnAPlate {
    Scene scene;
    SimTK::MobilizedBody::Free plate = scene.addFree(1.0, 0.05);
    std::vector<SimTK::MobilizedBody::Free> spheres;
    ContactParameters parameters = test::makeParameters(kEStar, kDissipation, 0.6, 0.4, 0.01);
    CompliantContactForce force;
    SimTK::State state;

    // (x, y, depth, vertical speed, sliding speed along x) per sphere.
    const double layout[5][5] = {{0.00, 0.00, 0.0020, +2.0, 0.000},
                                 {0.03, 0.00, 0.0010, -0.1, 0.005},
                                 {-0.03, 0.01, 0.0015, 0.0, 0.020},
                                 {0.00, -0.02, 0.0005, +0.2, 0.000},
                                 {0.04, 0.02, 0.0025, -0.3, -0.010}};

    FiveSpheresOnAPlate() {
        std::vector<ContactPair> pairs;
        const ContactShape plateShape = ContactShape::box(Vec3(0.06, 0.04, 0.02));
        for (int i = 0; i < 5; ++i) {
            spheres.push_back(scene.addFree(0.01, kRadius));
            pairs.push_back({test::makeSurface(spheres[i], "sphere" + std::to_string(i),
                                               ContactShape::sphere(kRadius)),
                             test::makeSurface(plate, "plate", plateShape), parameters});
        }
        force = CompliantContactForce(scene.forces, pairs);
        state = scene.system.realizeTopology();
        scene.system.realizeModel(state);
        for (int i = 0; i < 5; ++i) {
            const double* s = layout[i];
            spheres[i].setQToFitTranslation(state, Vec3(s[0], s[1], 0.02 + kRadius - s[2]));
            spheres[i].setUToFitLinearVelocity(state, Vec3(s[4], 0, s[3]));
        }
        scene.system.realize(state, SimTK::Stage::Dynamics);
    }
};

TEST(CompliantContactForce, EveryContactCountsEvenAfterOneWithZeroForce) {
    FiveSpheresOnAPlate s;
    const ContactParameters& p = s.parameters;
    // Oracle: each contact evaluated on its own (geometry from findContacts, force law by hand:
    // f_n = max(0, (4/3) E* sqrt(R) x^1.5 (1 + 1.5 c xdot)), friction -mu f_n v/|v|).
    Vec3 force_G(0), torque_G(0);
    const Vec3 p_GPlate = s.plate.getBodyOriginLocation(s.state);
    int positiveContacts = 0;
    for (int i = 0; i < 5; ++i) {
        const double* l = s.layout[i];
        const std::vector<ContactPoint> contacts =
            findContacts(ContactShape::sphere(kRadius), s.spheres[i].getBodyTransform(s.state),
                         ContactShape::box(Vec3(0.06, 0.04, 0.02)), Transform());
        ASSERT_EQ(contacts.size(), 1u);
        const double x = l[2], xdot = -l[3];  // sphere moving down deepens the contact
        const double fn = std::max(
            0.0, 4.0 / 3.0 * kEStar * std::sqrt(kRadius) * std::pow(x, 1.5) * (1 + 1.5 * xdot));
        positiveContacts += fn > 0;
        // The plate (b) slips at -v_sphere relative to the sphere (a).
        const Vec3 F = fn * Vec3(0, 0, -1) + calcFrictionForce(p, fn, Vec3(-l[4], 0, 0));
        force_G += F;
        torque_G += (contacts[0].p_G - p_GPlate) % F;
    }
    ASSERT_EQ(positiveContacts, 4);  // sphere 0's force is clamped to zero
    const SpatialVec& plateForce = s.scene.system.getRigidBodyForces(
        s.state, SimTK::Stage::Dynamics)[s.plate.getMobilizedBodyIndex()];
    EXPECT_LE((plateForce[1] - force_G).norm(), 1e-9 * force_G.norm()) << plateForce[1];
    EXPECT_LE((plateForce[0] - torque_G).norm(), 1e-9 * force_G.norm()) << plateForce[0];
    // Each sphere gets the opposite of its own contact force.
    const std::vector<ContactReport> reports = s.force.findContactReports(s.state);
    ASSERT_EQ(reports.size(), 5u);
    for (const ContactReport& r : reports) {
        const SpatialVec& sphereForce = s.scene.system.getRigidBodyForces(
            s.state, SimTK::Stage::Dynamics)[s.spheres[r.pairIndex].getMobilizedBodyIndex()];
        const Vec3 F = r.normalForce * r.n_G.asVec3() + r.frictionForce_G;
        EXPECT_LE((sphereForce[1] + F).norm(), 1e-12) << "pair " << r.pairIndex;
    }
    EXPECT_EQ(reports[0].normalForce, 0.0);
}

TEST(CompliantContactForce, ReportsNameBodiesAndGiveForcesOfEachContact) {
    FiveSpheresOnAPlate s;
    const std::vector<ContactReport> reports = s.force.findContactReports(s.state);
    ASSERT_EQ(reports.size(), 5u);
    const ContactReport& r = reports[2];  // 1.5 mm deep, at rest vertically, sliding 20 mm/s
    EXPECT_EQ(r.pairIndex, 2);
    EXPECT_EQ(r.bodyA, "sphere2");
    EXPECT_EQ(r.bodyB, "plate");
    EXPECT_EQ(r.shapeB, "plate_shape");
    EXPECT_NEAR(r.depth, 0.0015, 1e-15);
    EXPECT_NEAR(r.depthRate, 0.0, 1e-15);
    EXPECT_LE((r.p_G - Vec3(-0.03, 0.01, 0.02 - 0.00075)).norm(), 1e-15);
    EXPECT_LE((r.n_G.asVec3() - Vec3(0, 0, -1)).norm(), 1e-15);
    const double fn = 4.0 / 3.0 * kEStar * std::sqrt(kRadius) * std::pow(0.0015, 1.5);
    EXPECT_NEAR(r.normalForce, fn, 1e-12 * fn);
    EXPECT_LE((r.slipVelocity_G - Vec3(-0.02, 0, 0)).norm(), 1e-15);
    // 0.02 m/s = 2 vt: mu = 0.4 + 2 (0.6 - 0.4) / (1 + 4) = 0.48, pushing the plate along +x.
    EXPECT_LE((r.frictionForce_G - Vec3(0.48 * fn, 0, 0)).norm(), 1e-12 * fn);
}

// The pair's capsule rule reaches the element: a capsule lying flat 1 mm deep on the plate,
// tilted so that one end is 0.2 mm deeper, presses at its deeper end alone under Deepest, at both
// ends with the Hertz force of each end's depth under Ends.
TEST(CompliantContactForce, ThePairsCapsuleRuleChoosesWhereACapsulePresses) {
    for (const CapsuleContact rule : {CapsuleContact::Deepest, CapsuleContact::Ends}) {
        Scene scene;
        const SimTK::MobilizedBody::Free plate = scene.addFree(1.0, 0.05);
        const SimTK::MobilizedBody::Free finger = scene.addFree(0.01, kRadius);
        ContactParameters parameters = test::makeParameters(kEStar, kDissipation, 0.6, 0.4, 0.01);
        parameters.capsuleContact = rule;
        const double length = 0.04, tilt = std::asin(0.0002 / length);
        const CompliantContactForce force(
            scene.forces, {{test::makeSurface(finger, "finger", ContactShape::capsule(kRadius, length)),
                            test::makeSurface(plate, "plate", ContactShape::box(Vec3(0.06, 0.04, 0.02))), parameters}});
        SimTK::State state = scene.system.realizeTopology();
        scene.system.realizeModel(state);
        // Core along x, its x > 0 end 0.2 mm lower; its centre 0.9 mm deep.
        finger.setQToFitTransform(state, Transform(SimTK::Rotation(SimTK::Pi / 2 + tilt, SimTK::YAxis),
                                                   Vec3(0, 0, 0.02 + kRadius - 0.0009)));
        scene.system.realize(state, SimTK::Stage::Dynamics);
        const std::vector<ContactReport> reports = force.findContactReports(state);
        const std::vector<double> depths =
            rule == CapsuleContact::Ends ? std::vector<double>{0.0008, 0.001} : std::vector<double>{0.001};
        ASSERT_EQ(reports.size(), depths.size()) << toString(rule);
        double total = 0;
        for (std::size_t k = 0; k < depths.size(); ++k) {
            EXPECT_NEAR(reports[k].depth, depths[k], 1e-12) << toString(rule);
            total += reports[k].normalForce;
        }
        double expected = 0;
        for (const double x : depths) expected += 4.0 / 3.0 * kEStar * std::sqrt(kRadius) * std::pow(x, 1.5);
        EXPECT_NEAR(total, expected, 1e-9 * expected) << toString(rule);
    }
}

TEST(CompliantContactForce, PotentialEnergyIsTheHertzEnergyOfEveryContact) {
    FiveSpheresOnAPlate s;
    double expected = 0;
    for (const auto& l : s.layout) {
        expected += 8.0 / 15.0 * kEStar * std::sqrt(kRadius) * std::pow(l[2], 2.5);
    }
    EXPECT_NEAR(s.force.calcPotentialEnergyContribution(s.state), expected, 1e-12 * expected);
}

TEST(CompliantContactForce, DisabledPairsExertNothingAndSwitchingInvalidatesInstance) {
    FiveSpheresOnAPlate s;
    const auto plateForce = [&] {
        s.scene.system.realize(s.state, SimTK::Stage::Dynamics);
        return s.scene.system.getRigidBodyForces(
            s.state, SimTK::Stage::Dynamics)[s.plate.getMobilizedBodyIndex()][1];
    };
    const Vec3 all = plateForce();
    const ContactReport r4 = s.force.findContactReports(s.state)[4];
    const Vec3 F4 = r4.normalForce * r4.n_G.asVec3() + r4.frictionForce_G;
    EXPECT_TRUE(s.force.isPairEnabled(s.state, 4));
    s.force.setPairEnabled(s.state, 4, false);
    EXPECT_LT(s.state.getSystemStage(), SimTK::Stage::Instance);
    EXPECT_FALSE(s.force.isPairEnabled(s.state, 4));
    EXPECT_LE((plateForce() - (all - F4)).norm(), 1e-12);
    EXPECT_EQ(s.force.findContactReports(s.state).size(), 4u);
    s.force.setPairsEnabled(s.state, {0, 1, 2, 3}, false);
    EXPECT_EQ(plateForce(), Vec3(0));
    EXPECT_EQ(s.force.calcPotentialEnergyContribution(s.state), 0.0);
    s.force.setPairsEnabled(s.state, {0, 1, 2, 3, 4}, true);
    EXPECT_LE((plateForce() - all).norm(), 1e-12);
}

// The reports of listed pairs do not depend on their flags: a disabled pair reports what it
// would apply if enabled (the engaged approximation measures the replaced fingertips this way),
// and the state is not invalidated; their depths alone are the reports' depths.
TEST(CompliantContactForce, ListedPairsReportAsIfEnabledWithoutTouchingTheState) {
    FiveSpheresOnAPlate s;
    const std::vector<ContactReport> enabled = s.force.findContactReports(s.state);
    s.force.setPairsEnabled(s.state, {1, 3}, false);
    s.scene.system.realize(s.state, SimTK::Stage::Velocity);

    const std::vector<ContactReport> listed = s.force.findContactReports(s.state, {3, 1});

    EXPECT_EQ(s.state.getSystemStage(), SimTK::Stage::Velocity);
    ASSERT_EQ(listed.size(), 2u);
    for (const ContactReport& r : listed) {
        const ContactReport& e = enabled[static_cast<std::size_t>(r.pairIndex)];
        EXPECT_EQ(r.depth, e.depth);
        EXPECT_EQ(r.normalForce, e.normalForce);
        EXPECT_EQ(r.frictionForce_G, e.frictionForce_G);
    }
    EXPECT_EQ(listed[0].pairIndex, 1);  // in pair order
    EXPECT_THROW(s.force.findContactReports(s.state, {5}), InputError);

    const std::vector<ContactDepth> depths = s.force.findContactDepths(s.state, {3, 1});
    ASSERT_EQ(depths.size(), listed.size());
    for (std::size_t k = 0; k < depths.size(); ++k) {
        EXPECT_EQ(depths[k].pairIndex, listed[k].pairIndex);
        EXPECT_EQ(depths[k].depth, listed[k].depth);
    }
    EXPECT_EQ(s.state.getSystemStage(), SimTK::Stage::Velocity);
    EXPECT_THROW(s.force.findContactDepths(s.state, {5}), InputError);
}

TEST(CompliantContactForce, PairsCanStartDisabledAndBadIndicesAreRejected) {
    Scene scene;
    const SimTK::MobilizedBody::Free ball = scene.addFree(0.1, 0.02);
    ContactPair pair{test::makeSurface(ball, "ball", ContactShape::sphere(0.02)), scene.makeFloor()};
    pair.enabledByDefault = false;
    const CompliantContactForce force(scene.forces, {pair});
    SimTK::State state = scene.system.realizeTopology();
    EXPECT_FALSE(force.isPairEnabled(state, 0));
    EXPECT_EQ(force.getNumPairs(), 1);
    EXPECT_EQ(force.findAllPairIndices(), std::vector<int>{0});
    EXPECT_EQ(force.getPair(0).a.bodyName, "ball");
    try {
        force.setPairEnabled(state, 1, true);
        FAIL() << "index 1 accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "contact pair index 1 is out of range; the element has 1 pairs (0 to 0)");
    }
    EXPECT_THROW(force.setPairsEnabled(state, {0, -1}, true), InputError);
    EXPECT_FALSE(force.isPairEnabled(state, 0));  // nothing changed by the failed call
}

TEST(CompliantContactForce, InvalidParametersAreRejectedNamingThePair) {
    Scene scene;
    const SimTK::MobilizedBody::Free ball = scene.addFree(0.1, 0.02);
    ContactPair pair{test::makeSurface(ball, "ball", ContactShape::sphere(0.02)), scene.makeFloor()};
    pair.parameters.staticFriction = 0;
    pair.parameters.dynamicFriction = 0.5;
    try {
        CompliantContactForce(scene.forces, {pair});
        FAIL() << "parameters accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "contact pair 'ball/ball_shape vs ground/floor': dynamicFriction "
                  "(0.5) is greater than staticFriction (0); it must be <= staticFriction");
    }
}

}  // namespace
}  // namespace graspsim::contact
