// Contacts of the hand's shapes (spheres, capsules, boxes) with the object shapes added to
// spheres, capsules and boxes: cylinder, ellipsoid and convex mesh. Oracles: hand-computed
// depth, normal, point and Hertz radius; the Hertz force by hand; a mesh of a box against the
// analytic box; a finely tessellated cylinder mesh against the analytic cylinder.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "contact_scenes.h"
#include "graspsim/contact/compliant_contact_force.h"
#include "graspsim/contact/rigid_contact_geometry.h"
#include "graspsim/contact/shape_contact.h"
#include "graspsim/error.h"
#include "test_meshes.h"

namespace graspsim::contact {
namespace {

using SimTK::Rotation;
using SimTK::Transform;
using SimTK::UnitVec3;
using SimTK::Vec3;

constexpr double kTip = 0.008;  // fingertip sphere radius (m)
constexpr double kEStar = 2e5;  // Pa

double combine(double a, double b) { return a * b / (a + b); }

// An object pose with a general rotation, so that frame bugs show.
const Transform X_GO(Rotation(SimTK::BodyRotationSequence, 0.3, SimTK::XAxis, -0.7, SimTK::YAxis,
                              1.1, SimTK::ZAxis),
                     Vec3(0.1, -0.2, 0.3));

// The only contact of a fingertip whose centre is at p_O in the object frame: checks depth,
// normal (from fingertip into the object: -n_O), point (midway between the surfaces along n)
// and Hertz radius.
void expectFingertipContact(const ContactShape& object, const Vec3& centre_O, double depth,
                            const Vec3& n_O, double radius, double tolerance = 1e-12) {
    const ContactShape tip = ContactShape::sphere(kTip);
    const Transform X_GT(X_GO * centre_O);
    const std::vector<ContactPoint> contacts = findContacts(tip, X_GT, object, X_GO);
    ASSERT_EQ(contacts.size(), 1u);
    const ContactPoint& c = contacts[0];
    EXPECT_NEAR(c.depth, depth, tolerance);
    EXPECT_LE((c.n_G.asVec3() + X_GO.R() * n_O).norm(), tolerance) << c.n_G;
    const Vec3 expectedPoint = X_GO * (centre_O - (kTip - 0.5 * depth) * n_O);
    EXPECT_LE((c.p_G - expectedPoint).norm(), tolerance) << c.p_G;
    EXPECT_NEAR(c.radius, radius, 1e-15);
}

// The normal force CompliantContactForce reports for a fingertip at rest at p_O against the
// object at rest: the Hertz law (4/3) E* sqrt(R) x^(3/2), by hand.
void expectHertzForce(const ContactShape& object, const Vec3& centre_O, double depth, double radius) {
    test::Scene scene;
    SimTK::MobilizedBody::Free tipBody = scene.addFree(0.01, kTip);
    SimTK::MobilizedBody::Free objectBody = scene.addFree(0.2, 0.03);
    const ContactParameters parameters = test::makeParameters(kEStar, 0.5);
    CompliantContactForce force(scene.forces,
                                {{test::makeSurface(tipBody, "tip", ContactShape::sphere(kTip)),
                                  test::makeSurface(objectBody, "object", object), parameters}});
    SimTK::State state = scene.system.realizeTopology();
    objectBody.setQToFitTransform(state, X_GO);
    tipBody.setQToFitTranslation(state, X_GO * centre_O);
    scene.system.realize(state, SimTK::Stage::Dynamics);
    const std::vector<ContactReport> reports = force.findContactReports(state);
    ASSERT_EQ(reports.size(), 1u);
    const double expected = 4.0 / 3.0 * kEStar * std::sqrt(radius) * std::pow(depth, 1.5);
    EXPECT_NEAR(reports[0].normalForce, expected, 1e-9 * expected);
    EXPECT_GT(expected, 0.01);  // a force worth checking (N)
}

// Every contact of (b, a) equals one of (a, b) with the normal negated, and vice versa.
void expectMirrored(const ContactShape& a, const Transform& X_GA, const ContactShape& b,
                    const Transform& X_GB) {
    const std::vector<ContactPoint> ab = findContacts(a, X_GA, b, X_GB);
    const std::vector<ContactPoint> ba = findContacts(b, X_GB, a, X_GA);
    ASSERT_EQ(ab.size(), ba.size());
    EXPECT_FALSE(ab.empty());
    for (const ContactPoint& c : ab) {
        bool matched = false;
        for (const ContactPoint& m : ba) {
            matched = matched || ((c.p_G - m.p_G).norm() < 1e-12 &&
                                  (c.n_G.asVec3() + m.n_G.asVec3()).norm() < 1e-12 &&
                                  std::abs(c.depth - m.depth) < 1e-12 && c.radius == m.radius);
        }
        EXPECT_TRUE(matched) << "contact at " << c.p_G << " has no mirror";
    }
}

// ---- cylinder -------------------------------------------------------------------------

const ContactShape kCylinder = ContactShape::cylinder(0.03, 0.1);

TEST(ObjectShapeContact, FingertipOnCylinderSideCapAndRim) {
    // Side: the curved surface's radius 0.03 in the cross-section combines with the tip's.
    const UnitVec3 radial(1, 1, 0);
    const Vec3 side = (0.03 + kTip - 0.001) * radial.asVec3() + Vec3(0, 0, 0.02);
    expectFingertipContact(kCylinder, side, 0.001, radial.asVec3(), combine(kTip, 0.03));
    expectHertzForce(kCylinder, side, 0.001, combine(kTip, 0.03));
    // Cap: flat.
    const Vec3 cap(0.01, -0.005, 0.05 + kTip - 0.002);
    expectFingertipContact(kCylinder, cap, 0.002, Vec3(0, 0, 1), kTip);
    expectHertzForce(kCylinder, cap, 0.002, kTip);
    // Rim: centre 5 mm from the rim along (4, 0, 3)/5; the rim counts like the faces it bounds.
    const Vec3 rim(0.03 + 0.004, 0, 0.05 + 0.003);
    expectFingertipContact(kCylinder, rim, kTip - 0.005, Vec3(0.8, 0, 0.6), kTip);
}

TEST(ObjectShapeContact, CapsuleAcrossACylinderAndArgumentOrder) {
    // A finger capsule lying across the cylinder's side, parallel to the surface (along x),
    // 1 mm deep at its middle.
    const ContactShape finger = ContactShape::capsule(0.009, 0.04);
    const Transform X_OF(Rotation(SimTK::Pi / 2, SimTK::YAxis), Vec3(0, 0.03 + 0.009 - 0.001, 0.01));
    const ContactPoint c = findContacts(finger, X_GO * X_OF, kCylinder, X_GO).at(0);
    EXPECT_NEAR(c.depth, 0.001, 1e-12);
    // Parallel to the side the contact sits mid-way along the flat stretch, found to the line
    // search's kFlatTolerance: the normal to ~1e-10.
    EXPECT_LE((c.n_G.asVec3() + X_GO.R() * Vec3(0, 1, 0)).norm(), 1e-9);
    EXPECT_NEAR(c.radius, combine(0.009, 0.03), 1e-15);
    expectMirrored(finger, X_GO * X_OF, kCylinder, X_GO);
}

// ---- ellipsoid ------------------------------------------------------------------------

const Vec3 kSemiAxes(0.04, 0.03, 0.02);
const ContactShape kEllipsoid = ContactShape::ellipsoid(kSemiAxes);

TEST(ObjectShapeContact, FingertipOnEllipsoidPoleUsesTheGaussianCurvatureRadius) {
    // At the pole (a, 0, 0) the principal radii are b^2/a and c^2/a: Gaussian radius b c / a.
    const double a = kSemiAxes[0], b = kSemiAxes[1], c = kSemiAxes[2];
    const Vec3 pole(a + kTip - 0.0015, 0, 0);
    expectFingertipContact(kEllipsoid, pole, 0.0015, Vec3(1, 0, 0), combine(kTip, b * c / a));
    expectHertzForce(kEllipsoid, pole, 0.0015, combine(kTip, b * c / a));
}

TEST(ObjectShapeContact, FingertipOnACurvedEllipsoidPoint) {
    // Surface point P at parametric angles (u, v); the outward normal there is
    // (x/a^2, y/b^2, z/c^2) normalized; a centre on that normal has P as nearest point.
    const double a = kSemiAxes[0], b = kSemiAxes[1], c = kSemiAxes[2];
    const double u = 0.7, v = -0.4;
    const Vec3 P(a * std::cos(v) * std::cos(u), b * std::cos(v) * std::sin(u), c * std::sin(v));
    const UnitVec3 n(Vec3(P[0] / (a * a), P[1] / (b * b), P[2] / (c * c)));
    // Gaussian curvature K = 1 / (a^2 b^2 c^2 (x^2/a^4 + y^2/b^4 + z^2/c^4)^2).
    const double s = P[0] * P[0] / std::pow(a, 4) + P[1] * P[1] / std::pow(b, 4) +
                     P[2] * P[2] / std::pow(c, 4);
    const double gaussianRadius = 1 / std::sqrt(1 / (a * a * b * b * c * c * s * s));
    const Vec3 centre = P + (kTip - 0.001) * n.asVec3();
    expectFingertipContact(kEllipsoid, centre, 0.001, n.asVec3(), combine(kTip, gaussianRadius), 1e-12);
    expectHertzForce(kEllipsoid, centre, 0.001, combine(kTip, gaussianRadius));
    expectMirrored(ContactShape::capsule(0.008, 0.03), Transform(X_GO * centre), kEllipsoid, X_GO);
}

// ---- convex mesh ----------------------------------------------------------------------

const Vec3 kPhone(0.035, 0.07, 0.0045);

TEST(ObjectShapeContact, FingertipOnAMeshFaceIsFlat) {
    const ContactShape mesh = test::makeMeshShape(test::makeBoxMesh(kPhone));
    const Vec3 face(0.01, 0.02, kPhone[2] + kTip - 0.002);
    expectFingertipContact(mesh, face, 0.002, Vec3(0, 0, 1), kTip);
    expectHertzForce(mesh, face, 0.002, kTip);
}

TEST(ObjectShapeContact, FingertipOnAMeshEdgeAndCorner) {
    const ContactShape mesh = test::makeMeshShape(test::makeBoxMesh(kPhone));
    // Outside the edge x = hx, z = hz: distance 5 mm along (3, 0, 4)/5; an edge counts like the
    // faces it bounds (the fingertip's radius alone).
    const Vec3 edge(kPhone[0] + 0.003, 0.01, kPhone[2] + 0.004);
    expectFingertipContact(mesh, edge, kTip - 0.005, Vec3(0.6, 0, 0.8), kTip);
    // Outside the corner (+, +, +) along (1, 2, 2)/3, 6 mm away.
    const Vec3 corner = kPhone + Vec3(0.002, 0.004, 0.004);
    expectFingertipContact(mesh, corner, kTip - 0.006, Vec3(1, 2, 2) / 3, kTip);
    expectMirrored(ContactShape::sphere(kTip), Transform(X_GO * corner), mesh, X_GO);
}

// Random sphere and capsule probes near the box give the same contact against its 12-triangle
// mesh as against the analytic box.
TEST(ObjectShapeContact, MeshOfABoxEqualsTheBoxForSweptProbes) {
    const ContactShape box = ContactShape::box(kPhone);
    const ContactShape mesh = test::makeMeshShape(test::makeBoxMesh(kPhone));
    std::mt19937 random(11);
    std::uniform_real_distribution<double> coordinate(-0.09, 0.09), angle(-SimTK::Pi, SimTK::Pi);
    int compared = 0;
    for (int i = 0; i < 400; ++i) {
        const ContactShape probe =
            i % 2 ? ContactShape::sphere(0.01) : ContactShape::capsule(0.009, 0.045);
        const Transform X_GP(Rotation(SimTK::BodyRotationSequence, angle(random), SimTK::XAxis,
                                      angle(random), SimTK::YAxis, angle(random), SimTK::ZAxis),
                             X_GO * Vec3(coordinate(random), coordinate(random), 0.3 * coordinate(random)));
        const std::vector<ContactPoint> expected = findContacts(probe, X_GP, box, X_GO);
        const std::vector<ContactPoint> actual = findContacts(probe, X_GP, mesh, X_GO);
        ASSERT_EQ(actual.size(), expected.size()) << "probe " << i;
        if (expected.empty()) continue;
        ++compared;
        EXPECT_NEAR(actual[0].depth, expected[0].depth, 1e-9) << "probe " << i;
        EXPECT_LE((actual[0].n_G.asVec3() - expected[0].n_G.asVec3()).norm(), 1e-9) << "probe " << i;
        EXPECT_LE((actual[0].p_G - expected[0].p_G).norm(), 1e-9) << "probe " << i;
        EXPECT_EQ(actual[0].radius, expected[0].radius);
    }
    EXPECT_GT(compared, 60);
}

// Each contact of `actual` matches one of `expected` (and the counts agree).
void expectSameContacts(const std::vector<ContactPoint>& actual,
                        const std::vector<ContactPoint>& expected, double tolerance,
                        const std::string& what) {
    ASSERT_EQ(actual.size(), expected.size()) << what;
    for (const ContactPoint& c : actual) {
        bool matched = false;
        for (const ContactPoint& e : expected) {
            matched = matched || ((c.p_G - e.p_G).norm() < tolerance &&
                                  (c.n_G.asVec3() - e.n_G.asVec3()).norm() < tolerance &&
                                  std::abs(c.depth - e.depth) < tolerance &&
                                  std::abs(c.radius - e.radius) < 1e-15);
        }
        EXPECT_TRUE(matched) << what << ": contact at " << c.p_G << " depth " << c.depth;
    }
}

// A corner pushed to the palm's mid-plane (where the box's depth is capped) is as deep below its
// upper face as below its lower: which face it is pushed out through is decided by rounding (a
// clang build and a gcc build choose differently), so such contacts compare nothing.
std::vector<ContactPoint> dropMidPlaneContacts(std::vector<ContactPoint> contacts, double halfThickness) {
    contacts.erase(std::remove_if(contacts.begin(), contacts.end(),
                                  [&](const ContactPoint& c) { return c.depth > halfThickness - 1e-9; }),
                   contacts.end());
    return contacts;
}

// A palm box pressed into a phone-sized box at random poses: the mesh of the phone gives the
// contacts of box vs box (vertices, edges, edge-edge crossings).
TEST(ObjectShapeContact, MeshOfABoxEqualsTheBoxForAPalmBox) {
    const ContactShape phone = ContactShape::box(kPhone);
    const ContactShape mesh = test::makeMeshShape(test::makeBoxMesh(kPhone));
    constexpr double kPalmHalfThickness = 0.01;
    const ContactShape palm = ContactShape::box(Vec3(0.04, 0.05, kPalmHalfThickness));
    std::mt19937 random(5);
    std::uniform_real_distribution<double> offset(-0.05, 0.05), angle(-SimTK::Pi, SimTK::Pi);
    int withContacts = 0;
    for (int i = 0; i < 300; ++i) {
        const Transform X_GP(Rotation(SimTK::BodyRotationSequence, angle(random), SimTK::XAxis,
                                      angle(random), SimTK::YAxis, angle(random), SimTK::ZAxis),
                             X_GO * Vec3(offset(random), offset(random), 0.6 * offset(random)));
        const std::vector<ContactPoint> expected =
            dropMidPlaneContacts(findContacts(palm, X_GP, phone, X_GO), kPalmHalfThickness);
        const std::vector<ContactPoint> actual =
            dropMidPlaneContacts(findContacts(palm, X_GP, mesh, X_GO), kPalmHalfThickness);
        withContacts += !expected.empty();
        expectSameContacts(actual, expected, 1e-9, "pose " + std::to_string(i));
        if (!expected.empty() && i % 10 == 0) expectMirrored(palm, X_GP, mesh, X_GO);
    }
    EXPECT_GT(withContacts, 100);
    // Palm face flat on the phone face, 1 mm deep: the phone's 4 upper vertices under the palm.
    const Transform X_OP(Vec3(0, 0, kPhone[2] + 0.01 - 0.001));
    expectSameContacts(findContacts(palm, X_GO * X_OP, mesh, X_GO),
                       findContacts(palm, X_GO * X_OP, phone, X_GO), 1e-12, "flat");
}

// A cylinder tessellated into 512 facets lies within r (1 - cos(pi/512)) of the cylinder, so the
// depths differ by at most that, and the normals by at most the facet half-angle.
TEST(ObjectShapeContact, FineCylinderMeshApproachesTheCylinder) {
    constexpr int kFacets = 512;
    const double r = 0.03, length = 0.1;
    const ContactShape mesh = test::makeMeshShape(test::makeCylinderMesh(r, length, kFacets));
    const double tessellation = r * (1 - std::cos(SimTK::Pi / kFacets));
    std::mt19937 random(2);
    std::uniform_real_distribution<double> angle(-SimTK::Pi, SimTK::Pi), height(-0.04, 0.04),
        depth(0.0002, 0.003);
    for (int i = 0; i < 60; ++i) {
        const double a = angle(random);
        const Vec3 centre = (r + kTip - depth(random)) * Vec3(std::cos(a), std::sin(a), 0) +
                            Vec3(0, 0, height(random));
        const ContactShape tip = ContactShape::sphere(kTip);
        const ContactPoint exact = findContacts(tip, Transform(X_GO * centre), kCylinder, X_GO).at(0);
        const ContactPoint meshed = findContacts(tip, Transform(X_GO * centre), mesh, X_GO).at(0);
        EXPECT_NEAR(meshed.depth, exact.depth, tessellation + 1e-12);
        EXPECT_LE((meshed.n_G.asVec3() - exact.n_G.asVec3()).norm(), SimTK::Pi / kFacets + 1e-12);
    }
}

// ---- palm box against the curved objects ------------------------------------------------

TEST(ObjectShapeContact, PalmBoxFaceOnCylinderSideAndEnd) {
    constexpr double kPalmHalfThickness = 0.01;
    const ContactShape palm = ContactShape::box(Vec3(0.04, 0.05, kPalmHalfThickness));
    const ContactShape cylinder = ContactShape::cylinder(0.03, 0.2);
    // Cylinder along x_O (its z turned onto x), palm above it, its lower face 1 mm into the top
    // line. Contacts: the side line's middle under the palm face (radius 0.03), and the palm's
    // two edges along y crossing the cylinder at x = +-0.04, each 1 mm deep (corner radius with
    // the cylinder's).
    const Transform X_OC(Rotation(SimTK::Pi / 2, SimTK::YAxis), Vec3(0));
    const Transform X_OP(Vec3(0, 0, 0.03 + 0.01 - 0.001));
    std::vector<ContactPoint> contacts = findContacts(palm, X_GO * X_OP, cylinder, X_GO * X_OC);
    ASSERT_EQ(contacts.size(), 3u);
    std::sort(contacts.begin(), contacts.end(), [](const ContactPoint& p, const ContactPoint& q) {
        return (~X_GO * p.p_G)[0] < (~X_GO * q.p_G)[0];
    });
    const Vec3 down = X_GO.R() * Vec3(0, 0, -1);
    const double xs[3] = {-0.04, 0, 0.04};
    const double radii[3] = {combine(0.005, 0.03), 0.03, combine(0.005, 0.03)};
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(contacts[k].depth, 0.001, 1e-12);
        EXPECT_LE((contacts[k].n_G.asVec3() - down).norm(), 1e-12);
        EXPECT_LE((contacts[k].p_G - X_GO * Vec3(xs[k], 0, 0.0295)).norm(), 1e-9);
        EXPECT_NEAR(contacts[k].radius, radii[k], 1e-15);
    }
    expectMirrored(palm, X_GO * X_OP, cylinder, X_GO * X_OC);
    // Cylinder standing on its cap under the palm: one contact at the cap's centre.
    const ContactShape can = ContactShape::cylinder(0.02, 0.1);
    const Transform X_OP2(Vec3(0.005, -0.01, 0.05 + 0.01 - 0.002));
    const ContactPoint c = findContacts(palm, X_GO * X_OP2, can, X_GO).at(0);
    EXPECT_NEAR(c.depth, 0.002, 1e-12);
    EXPECT_LE((c.p_G - X_GO * Vec3(0, 0, 0.049)).norm(), 1e-12);
    EXPECT_NEAR(c.radius, 0.02, 1e-15);
}

TEST(ObjectShapeContact, PalmBoxFaceOnEllipsoidPole) {
    constexpr double kPalmHalfThickness = 0.01;
    const ContactShape palm = ContactShape::box(Vec3(0.04, 0.05, kPalmHalfThickness));
    const double a = kSemiAxes[0], b = kSemiAxes[1], c = kSemiAxes[2];
    const Transform X_OP(Vec3(0.003, 0.002, c + 0.01 - 0.0012));
    const std::vector<ContactPoint> contacts = findContacts(palm, X_GO * X_OP, kEllipsoid, X_GO);
    ASSERT_EQ(contacts.size(), 1u);
    EXPECT_NEAR(contacts[0].depth, 0.0012, 1e-12);
    EXPECT_LE((contacts[0].n_G.asVec3() - X_GO.R() * Vec3(0, 0, -1)).norm(), 1e-12);
    EXPECT_LE((contacts[0].p_G - X_GO * Vec3(0, 0, c - 0.0006)).norm(), 1e-12);
    EXPECT_NEAR(contacts[0].radius, a * b / c, 1e-15);  // flat palm: the pole's Gaussian radius
    expectMirrored(palm, X_GO * X_OP, kEllipsoid, X_GO);
    // A palm corner pressed into the ellipsoid's side: one vertex contact, its depth the
    // ellipsoid's signed distance there.
    const Transform X_OCorner(Vec3(a - 0.001 + 0.04, 0.05, 0.01));
    const std::vector<ContactPoint> corner = findContacts(palm, X_GO * X_OCorner, kEllipsoid, X_GO);
    ASSERT_EQ(corner.size(), 1u);
    EXPECT_NEAR(corner[0].depth, 0.001, 1e-12);
    EXPECT_NEAR(corner[0].radius, combine(0.005, b * c / a), 1e-15);
}

// A capsule object (already a swept sphere) lying on the palm face along the palm's x: one
// contact at the middle of the flat stretch, the capsule's radius.
TEST(ObjectShapeContact, CapsuleObjectOnThePalm) {
    constexpr double kPalmHalfThickness = 0.01;
    const ContactShape palm = ContactShape::box(Vec3(0.04, 0.05, kPalmHalfThickness));
    const ContactShape bottle = ContactShape::capsule(0.025, 0.06);
    const Transform X_OB(Rotation(SimTK::Pi / 2, SimTK::YAxis), Vec3(0.01, 0, 0.01 + 0.025 - 0.002));
    const std::vector<ContactPoint> contacts = findContacts(palm, X_GO, bottle, X_GO * X_OB);
    ASSERT_EQ(contacts.size(), 1u);
    EXPECT_NEAR(contacts[0].depth, 0.002, 1e-12);
    // The flat stretch is the part of the axis over the palm, x in [-0.02, 0.04]: middle 0.01.
    EXPECT_LE((contacts[0].p_G - X_GO * Vec3(0.01, 0, 0.009)).norm(), 1e-9);
    EXPECT_LE((contacts[0].n_G.asVec3() - X_GO.R() * Vec3(0, 0, 1)).norm(), 1e-12);
    EXPECT_NEAR(contacts[0].radius, 0.025, 1e-15);
    expectMirrored(palm, X_GO, bottle, X_GO * X_OB);
}

// Random poses of every hand shape against every object shape: contacts have positive depth,
// unit normals, finite points and radii, and the two argument orders agree.
TEST(ObjectShapeContact, RandomPosesGiveSaneMirroredContacts) {
    const ContactShape hands[] = {ContactShape::sphere(kTip), ContactShape::capsule(0.009, 0.045),
                                  ContactShape::box(Vec3(0.04, 0.05, 0.01))};
    const ContactShape objects[] = {kCylinder, kEllipsoid, test::makeMeshShape(test::makeBoxMesh(kPhone)),
                                    test::makeMeshShape(test::makeCylinderMesh(0.03, 0.1, 12))};
    std::mt19937 random(8);
    std::uniform_real_distribution<double> coordinate(-0.07, 0.07), angle(-SimTK::Pi, SimTK::Pi);
    int contactCount = 0;
    for (const ContactShape& hand : hands) {
        for (const ContactShape& object : objects) {
            for (int i = 0; i < 60; ++i) {
                const Transform X_GH(Rotation(SimTK::BodyRotationSequence, angle(random), SimTK::XAxis,
                                              angle(random), SimTK::YAxis, angle(random), SimTK::ZAxis),
                                     X_GO * Vec3(coordinate(random), coordinate(random), coordinate(random)));
                const std::vector<ContactPoint> contacts = findContacts(hand, X_GH, object, X_GO);
                for (const ContactPoint& c : contacts) {
                    EXPECT_GT(c.depth, 0);
                    EXPECT_NEAR(c.n_G.asVec3().norm(), 1, 1e-12);
                    EXPECT_TRUE(c.p_G.isFinite());
                    EXPECT_TRUE(std::isfinite(c.radius) && c.radius > 0);
                }
                contactCount += static_cast<int>(contacts.size());
                if (!contacts.empty()) expectMirrored(hand, X_GH, object, X_GO);
            }
        }
    }
    EXPECT_GT(contactCount, 200);
}

// ---- integrated: a fingertip resting on each object ------------------------------------

// A 50 g fingertip sphere on a vertical Slider, resting under gravity on `object` fixed in
// Ground at X_GS with its top surface point at y = top and the surface's Hertz radius R there. Damped,
// it settles where the Hertz force carries its weight: depth (3 m g / (4 E* sqrt(R')))^(2/3)
// with R' the fingertip's radius combined with R.
void expectSettlesAtStaticHertzDepth(const ContactShape& object, const Transform& X_GS, double top,
                                     double objectRadius) {
    constexpr double kMass = 0.05, kG = 9.81;
    test::Scene scene;
    SimTK::Force::Gravity gravity(scene.forces, scene.matter, Vec3(0, -kG, 0));
    SimTK::MobilizedBody::Slider tip = scene.addSlider(SimTK::YAxis, kMass, kTip);
    const ContactParameters parameters = test::makeParameters(kEStar, 20);
    CompliantContactForce force(
        scene.forces, {{test::makeSurface(tip, "tip", ContactShape::sphere(kTip)),
                        {scene.matter.updGround(), "ground", "object", object, X_GS}, parameters}});
    SimTK::State state = scene.system.realizeTopology();
    tip.setOneQ(state, 0, top + kTip);  // touching, at rest
    SimTK::RungeKuttaMersonIntegrator integrator(scene.system);
    integrator.setAccuracy(1e-8);
    SimTK::TimeStepper stepper(scene.system, integrator);
    stepper.initialize(state);
    stepper.stepTo(0.3);
    const double depth = top + kTip - tip.getOneQ(integrator.getState(), 0);
    const double radius = std::isinf(objectRadius) ? kTip : combine(kTip, objectRadius);
    const double expected = test::calcStaticHertzDepth(kMass * kG, kEStar, radius);
    EXPECT_NEAR(depth, expected, 0.01 * expected);
    EXPECT_GT(expected, 1e-4);
}

TEST(ObjectShapeContact, FingertipRestsOnEachObjectAtTheStaticHertzDepth) {
    // Cylinder lying along x: top line at y = 0.03, radius 0.03 across.
    expectSettlesAtStaticHertzDepth(kCylinder, Transform(Rotation(SimTK::Pi / 2, SimTK::YAxis), Vec3(0)),
                                    0.03, 0.03);
    // Ellipsoid with its c axis up (z turned onto y): the pole, Gaussian radius a b / c.
    expectSettlesAtStaticHertzDepth(kEllipsoid, Transform(Rotation(-SimTK::Pi / 2, SimTK::XAxis), Vec3(0)),
                                    kSemiAxes[2], kSemiAxes[0] * kSemiAxes[1] / kSemiAxes[2]);
    // Mesh box lying flat: a flat face.
    expectSettlesAtStaticHertzDepth(test::makeMeshShape(test::makeBoxMesh(kPhone)),
                                    Transform(Rotation(-SimTK::Pi / 2, SimTK::XAxis), Vec3(0.005, 0, 0.01)),
                                    kPhone[2], SimTK::Infinity);
}

// A 300 g object on a vertical Slider resting under gravity on a fixed palm box (top face at
// y = 0): it settles where its contacts, all at the same depth x, carry its weight:
// m g = (4/3) E* x^(3/2) sum_i sqrt(R_i).
void expectObjectSettlesOnThePalm(const ContactShape& object, const SimTK::Rotation& R_GO, double bottom,
                                  const std::vector<double>& radii) {
    constexpr double kMass = 0.3, kG = 9.81;
    test::Scene scene;
    SimTK::Force::Gravity gravity(scene.forces, scene.matter, Vec3(0, -kG, 0));
    SimTK::MobilizedBody::Slider body = scene.addSlider(SimTK::YAxis, kMass, 0.03);
    const ContactParameters parameters = test::makeParameters(kEStar, 20);
    const ContactShape palm = ContactShape::box(Vec3(0.04, 0.01, 0.05));  // thin along y
    CompliantContactForce force(
        scene.forces, {{{scene.matter.updGround(), "ground", "palm", palm, Transform(Vec3(0, -0.01, 0))},
                        {body, "object", "object", object, Transform(R_GO, Vec3(0))}, parameters}});
    SimTK::State state = scene.system.realizeTopology();
    body.setOneQ(state, 0, bottom);  // touching, at rest
    SimTK::RungeKuttaMersonIntegrator integrator(scene.system);
    integrator.setAccuracy(1e-8);
    SimTK::TimeStepper stepper(scene.system, integrator);
    stepper.initialize(state);
    stepper.stepTo(0.3);
    double sumRoots = 0;
    for (double r : radii) sumRoots += std::sqrt(r);
    const double expected = std::pow(3 * kMass * kG / (4 * kEStar * sumRoots), 2.0 / 3.0);
    EXPECT_NEAR(bottom - body.getOneQ(integrator.getState(), 0), expected, 0.01 * expected);
    EXPECT_EQ(force.findContactReports(integrator.getState()).size(), radii.size());
}

TEST(ObjectShapeContact, ObjectsRestOnThePalmAtTheStaticHertzDepth) {
    // Cylinder along x, longer than the palm: its side line's middle (radius 0.03) and the two
    // palm edges along z crossing it (corner radius with the cylinder's).
    expectObjectSettlesOnThePalm(ContactShape::cylinder(0.03, 0.2), Rotation(SimTK::Pi / 2, SimTK::YAxis),
                                 0.03, {0.03, combine(0.005, 0.03), combine(0.005, 0.03)});
    // Ellipsoid with its c axis down (z onto y): the pole, Gaussian radius a b / c.
    expectObjectSettlesOnThePalm(kEllipsoid, Rotation(-SimTK::Pi / 2, SimTK::XAxis), kSemiAxes[2],
                                 {kSemiAxes[0] * kSemiAxes[1] / kSemiAxes[2]});
}

// ---- half-space, rejected pairs, rigid geometry -----------------------------------------

TEST(ObjectShapeContact, ObjectsOnAFloor) {
    const Transform floor = test::makeFloorPose();  // y-up floor at y = 0
    const ContactShape ground = ContactShape::halfSpace();
    // Cylinder lying along x, 1 mm into the floor: one contact mid-side with its radius.
    const ContactPoint lying =
        findContacts(kCylinder, Transform(Rotation(SimTK::Pi / 2, SimTK::YAxis), Vec3(0.2, 0.029, 0)),
                     ground, floor).at(0);
    EXPECT_NEAR(lying.depth, 0.001, 1e-12);
    EXPECT_LE((lying.p_G - Vec3(0.2, -0.0005, 0)).norm(), 1e-12);
    EXPECT_NEAR(lying.radius, 0.03, 1e-15);
    EXPECT_LE((lying.n_G.asVec3() - Vec3(0, -1, 0)).norm(), 1e-15);
    // Ellipsoid standing on its c axis (z turned onto y): the pole, Gaussian radius a b / c.
    const ContactPoint pole = findContacts(ground, floor, kEllipsoid,
                                           Transform(Rotation(-SimTK::Pi / 2, SimTK::XAxis),
                                                     Vec3(0, kSemiAxes[2] - 0.002, 0))).at(0);
    EXPECT_NEAR(pole.depth, 0.002, 1e-12);
    EXPECT_LE((pole.n_G.asVec3() - Vec3(0, 1, 0)).norm(), 1e-15);  // from the floor up
    EXPECT_NEAR(pole.radius, kSemiAxes[0] * kSemiAxes[1] / kSemiAxes[2], 1e-15);
    // A mesh box lying flat: its 4 lower vertices, as the analytic box.
    const ContactShape mesh = test::makeMeshShape(test::makeBoxMesh(kPhone));
    const Transform X_GM(Rotation(-SimTK::Pi / 2, SimTK::XAxis), Vec3(0, kPhone[2] - 0.001, 0));
    expectSameContacts(findContacts(mesh, X_GM, ground, floor),
                       findContacts(ContactShape::box(kPhone), X_GM, ground, floor), 1e-12, "floor");
    EXPECT_EQ(findContacts(mesh, X_GM, ground, floor).size(), 4u);
    expectMirrored(mesh, X_GM, ground, floor);
}

TEST(ObjectShapeContact, TwoObjectSolidsAreRejected) {
    EXPECT_THROW(findContacts(kCylinder, Transform(), kEllipsoid, Transform()), InputError);
}

TEST(ObjectShapeContact, RigidGapOfAFingertipIsExactForEveryObjectShape) {
    const ContactShape tip = ContactShape::sphere(kTip);
    const ContactShape mesh = test::makeMeshShape(test::makeBoxMesh(kPhone));
    // Fingertip 3 mm from the cylinder's side, the ellipsoid's pole, the mesh's face.
    const struct {
        const ContactShape* object;
        Vec3 centre_O;
        Vec3 n_O;
    } cases[] = {{&kCylinder, Vec3(0, 0.03 + kTip + 0.003, 0), Vec3(0, 1, 0)},
                 {&kEllipsoid, Vec3(0, 0, kSemiAxes[2] + kTip + 0.003), Vec3(0, 0, 1)},
                 {&mesh, Vec3(0.01, 0.01, kPhone[2] + kTip + 0.003), Vec3(0, 0, 1)}};
    for (const auto& c : cases) {
        const RigidContactGeometry g =
            findRigidContactGeometry(tip, Transform(X_GO * c.centre_O), *c.object, X_GO, 0.001);
        EXPECT_NEAR(g.separation, 0.003, 1e-12);
        EXPECT_LE((g.n_F.asVec3() + X_GO.R() * c.n_O).norm(), 1e-12);
    }
}

}  // namespace
}  // namespace graspsim::contact
