#include "graspsim/contact/shape_contact.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "graspsim/error.h"

namespace graspsim::contact {
namespace {

using SimTK::Rotation;
using SimTK::Transform;
using SimTK::UnitVec3;
using SimTK::Vec3;

const double kSqrt2 = std::sqrt(2.0);
const double kSqrt3 = std::sqrt(3.0);

void expectVecNear(const Vec3& actual, const Vec3& expected, double tolerance,
                   const std::string& what) {
    EXPECT_LE((actual - expected).norm(), tolerance)
        << what << ": got " << actual << ", expected " << expected;
}

// Checks one contact against hand-computed point, normal (A to B), depth and Hertz radius.
void expectContact(const ContactPoint& c, const Vec3& p_G, const Vec3& n_G, double depth,
                   double radius, double tolerance = 1e-12) {
    expectVecNear(c.p_G, p_G, tolerance, "point");
    expectVecNear(c.n_G.asVec3(), n_G, tolerance, "normal");
    EXPECT_NEAR(c.depth, depth, tolerance);
    EXPECT_NEAR(c.radius, radius, 1e-15);
}

ContactPoint findOnlyContact(const ContactShape& a, const Transform& X_GA, const ContactShape& b,
                             const Transform& X_GB) {
    const std::vector<ContactPoint> contacts = findContacts(a, X_GA, b, X_GB);
    EXPECT_EQ(contacts.size(), 1u);
    return contacts.empty() ? ContactPoint{} : contacts.front();
}

// Every contact of (b, a) equals one of (a, b) with the normal negated, and vice versa.
void expectMirrored(const ContactShape& a, const Transform& X_GA, const ContactShape& b,
                    const Transform& X_GB) {
    const std::vector<ContactPoint> ab = findContacts(a, X_GA, b, X_GB);
    const std::vector<ContactPoint> ba = findContacts(b, X_GB, a, X_GA);
    ASSERT_EQ(ab.size(), ba.size());
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

// Ground pose turning S's z axis into Ground's +y (a y-up floor for a half-space).
const Transform kFloor(Rotation(-SimTK::Pi / 2, SimTK::XAxis), Vec3(0));

// ---- swept sphere vs swept sphere -------------------------------------------------------

TEST(ShapeContact, SphereSphereDepthPointNormalAndRadius) {
    const ContactShape a = ContactShape::sphere(0.02), b = ContactShape::sphere(0.03);
    const Transform X_GA(Vec3(0.1, 0.2, 0.3));
    const Transform X_GB(Vec3(0.1 + 0.045, 0.2, 0.3));
    // Surfaces at x = 0.02 (A) and 0.045 - 0.03 = 0.015 (B): depth 0.005, midpoint 0.0175.
    expectContact(findOnlyContact(a, X_GA, b, X_GB), Vec3(0.1175, 0.2, 0.3), Vec3(1, 0, 0), 0.005,
                  0.02 * 0.03 / 0.05);
    expectMirrored(a, X_GA, b, X_GB);
}

TEST(ShapeContact, SeparatedOrTouchingShapesHaveNoContact) {
    const ContactShape s = ContactShape::sphere(0.02);
    EXPECT_TRUE(findContacts(s, Transform(), s, Transform(Vec3(0.0401, 0, 0))).empty());
    EXPECT_TRUE(findContacts(s, Transform(), s, Transform(Vec3(0.04, 0, 0))).empty());
    const ContactShape box = ContactShape::box(Vec3(0.05, 0.03, 0.02));
    const ContactShape capsule = ContactShape::capsule(0.01, 0.04);
    EXPECT_TRUE(findContacts(capsule, Transform(Vec3(0, 0, 0.051)), box, Transform()).empty());
    EXPECT_TRUE(findContacts(box, Transform(Vec3(0.1001, 0, 0)), box, Transform()).empty());
    EXPECT_TRUE(
        findContacts(s, Transform(Vec3(0, 0.0201, 0)), ContactShape::halfSpace(), kFloor).empty());
}

TEST(ShapeContact, CapsuleSideAgainstSphere) {
    // Capsule radius 10 mm, axis 40 mm along Ground x (S's z turned onto x).
    const ContactShape capsule = ContactShape::capsule(0.01, 0.04);
    const Transform X_GA(Rotation(SimTK::Pi / 2, SimTK::YAxis), Vec3(0));
    const ContactShape sphere = ContactShape::sphere(0.02);
    const Transform X_GB(Vec3(0.01, 0.025, 0));
    // Core point (0.01, 0, 0), centre distance 0.025, reach 0.03: depth 0.005 along +y;
    // surfaces at y = 0.01 and 0.005, midpoint 0.0075.
    expectContact(findOnlyContact(capsule, X_GA, sphere, X_GB), Vec3(0.01, 0.0075, 0),
                  Vec3(0, 1, 0), 0.005, 0.01 * 0.02 / 0.03, 1e-15);
    expectMirrored(capsule, X_GA, sphere, X_GB);
}

TEST(ShapeContact, CapsuleCapAgainstSphere) {
    const ContactShape capsule = ContactShape::capsule(0.01, 0.04);  // cap centre at z = 0.02
    const ContactShape sphere = ContactShape::sphere(0.02);
    const UnitVec3 direction(1, 0, 1);  // 45 degrees off the axis, over the cap
    const Transform X_GB(Vec3(0, 0, 0.02) + 0.026 * direction.asVec3());
    const Vec3 capCentre(0, 0, 0.02);
    // Centre distance 0.026 from the cap centre, reach 0.03: depth 0.004; surfaces at 0.01 and
    // 0.006 from the cap centre along the direction, midpoint 0.008.
    expectContact(findOnlyContact(capsule, Transform(), sphere, X_GB),
                  capCentre + 0.008 * direction.asVec3(), direction.asVec3(), 0.004,
                  0.01 * 0.02 / 0.03, 1e-15);
    expectMirrored(capsule, Transform(), sphere, X_GB);
}

TEST(ShapeContact, CapsuleCapsuleCrossedAndParallel) {
    const ContactShape capsule = ContactShape::capsule(0.01, 0.04);
    // Crossed: B's axis along x, 0.018 above A's axis (along z): depth 0.002 at the crossing.
    const Transform X_GB(Rotation(SimTK::Pi / 2, SimTK::YAxis), Vec3(0, 0.018, 0.005));
    expectContact(findOnlyContact(capsule, Transform(), capsule, X_GB), Vec3(0, 0.009, 0.005),
                  Vec3(0, 1, 0), 0.002, 0.005, 1e-10);
    // Parallel, B shifted 0.03 along the axis: overlap z in [0.01, 0.02] of A; middle z = 0.015.
    const Transform X_GP(Vec3(0, 0.018, 0.03));
    expectContact(findOnlyContact(capsule, Transform(), capsule, X_GP), Vec3(0, 0.009, 0.015),
                  Vec3(0, 1, 0), 0.002, 0.005, 1e-10);
    expectMirrored(capsule, Transform(), capsule, X_GB);
    expectMirrored(capsule, Transform(), capsule, X_GP);
}

// ---- sphere vs box ----------------------------------------------------------------------

const Vec3 kH(0.05, 0.03, 0.02);  // box half-lengths

TEST(ShapeContact, SphereOutsideBoxFaceEdgeAndCorner) {
    const ContactShape box = ContactShape::box(kH);
    const ContactShape sphere = ContactShape::sphere(0.01);
    // Face: centre 8 mm above the top face; depth 2 mm; surfaces at z = 0.02 and 0.018.
    const Transform onFace(Vec3(0.01, -0.01, 0.028));
    expectContact(findOnlyContact(sphere, onFace, box, Transform()), Vec3(0.01, -0.01, 0.019),
                  Vec3(0, 0, -1), 0.002, 0.01);
    expectMirrored(sphere, onFace, box, Transform());
    // Edge x = hx, z = hz: centre 6 mm out along each axis, distance 6 sqrt 2 mm.
    const Vec3 edge(kH[0], 0.005, kH[2]);
    const UnitVec3 out(1, 0, 1);
    const Transform onEdge(edge + Vec3(0.006, 0, 0.006));
    const double edgeDistance = 0.006 * kSqrt2;
    // Box surface point: the edge point; sphere surface point: centre - r out.
    expectContact(findOnlyContact(box, Transform(), sphere, onEdge),
                  edge + (0.5 * (edgeDistance - 0.01)) * out.asVec3(), out.asVec3(),
                  0.01 - edgeDistance, 0.01);
    // Corner: centre 5 mm out along each axis, distance 5 sqrt 3 mm.
    const Vec3 corner = kH;
    const UnitVec3 diagonal(1, 1, 1);
    const double cornerDistance = 0.005 * kSqrt3;
    const Transform onCorner(corner + Vec3(0.005));
    // Surfaces at the corner (box) and at cornerDistance - 0.01 along the diagonal (sphere).
    expectContact(findOnlyContact(box, Transform(), sphere, onCorner),
                  corner + (0.5 * (cornerDistance - 0.01)) * diagonal.asVec3(), diagonal.asVec3(),
                  0.01 - cornerDistance, 0.01);
    expectMirrored(box, Transform(), sphere, onCorner);
}

TEST(ShapeContact, SphereCentreInsideBox) {
    const ContactShape box = ContactShape::box(kH);
    const ContactShape sphere = ContactShape::sphere(0.01);
    // 5 mm below the top face, far from the others: signed distance -0.005, depth 0.015;
    // box surface at z = 0.02, sphere surface at z = 0.005, midpoint 0.0125.
    expectContact(findOnlyContact(box, Transform(), sphere, Transform(Vec3(0, 0, 0.015))),
                  Vec3(0, 0, 0.0125), Vec3(0, 0, 1), 0.015, 0.01);
    // Equally deep (5 mm) below the +x, +y and +z faces: the normal is their normalized sum.
    const Vec3 centre = kH - Vec3(0.005);
    const UnitVec3 diagonal(1, 1, 1);
    // Box surface 5 mm out along the diagonal, sphere surface 10 mm in: midpoint 2.5 mm in.
    expectContact(findOnlyContact(box, Transform(), sphere, Transform(centre)),
                  centre - 0.0025 * diagonal.asVec3(), diagonal.asVec3(), 0.015, 0.01);
}

// ---- capsule vs box ---------------------------------------------------------------------

TEST(ShapeContact, CapsuleCrossingBoxFaceTouchesAtItsDeepestEnd) {
    const ContactShape box = ContactShape::box(kH);
    // Axis from (-0.02, 0, 0.045) down to (0.01, 0, 0.015), entering through the top face; the
    // lower end is 5 mm below the top face (the nearest face there): depth 0.005 + 0.005.
    const Vec3 p0(-0.02, 0, 0.045), p1(0.01, 0, 0.015);
    const Transform X_GA(Rotation(UnitVec3(p1 - p0), SimTK::ZAxis), 0.5 * (p0 + p1));
    const ContactShape crossing = ContactShape::capsule(0.005, (p1 - p0).norm());
    // Box surface point z = 0.02, capsule surface point z = 0.015 - 0.005: midpoint z = 0.015.
    expectContact(findOnlyContact(crossing, X_GA, box, Transform()), Vec3(0.01, 0, 0.015),
                  Vec3(0, 0, -1), 0.01, 0.005, 1e-10);
    expectMirrored(crossing, X_GA, box, Transform());
}

TEST(ShapeContact, CapsuleLyingParallelOnBoxFaceTouchesAtMiddleOfFlatInterval) {
    const ContactShape box = ContactShape::box(kH);
    const ContactShape capsule = ContactShape::capsule(0.005, 0.04);
    const Rotation alongX(SimTK::Pi / 2, SimTK::YAxis);
    // Axis x in [-0.01, 0.03], 4 mm above the top face: depth 1 mm over the whole axis; the
    // contact goes to the axis middle, x = 0.01.
    // Box surface at z = 0.02, capsule surface at 0.024 - 0.005: midpoint 0.0195.
    const Transform onFace(alongX, Vec3(0.01, 0.005, 0.024));
    expectContact(findOnlyContact(capsule, onFace, box, Transform()), Vec3(0.01, 0.005, 0.0195),
                  Vec3(0, 0, -1), 0.001, 0.005, 1e-10);
    // Axis x in [0.03, 0.07] overhangs the face (hx = 0.05): flat over [0.03, 0.05] only, so
    // the contact is at x = 0.04 (not at the capsule's middle 0.05, nor at an end). Past the
    // edge the distance rises smoothly, which widens the flat interval found to tolerance 1e-14
    // by sqrt(2 * 0.004 * 1e-14) = 9e-9 m (see kFlatTolerance).
    const Transform overhanging(alongX, Vec3(0.05, 0.005, 0.024));
    expectContact(findOnlyContact(capsule, overhanging, box, Transform()),
                  Vec3(0.04, 0.005, 0.0195), Vec3(0, 0, -1), 0.001, 0.005, 1e-8);
    expectMirrored(capsule, overhanging, box, Transform());
    // Tilted by 1e-4 rad (x = 0.03 end down) the flat interval shrinks to that end: the level
    // set within 1e-14 m of the minimum is 1e-14 / sin 1e-4 = 1e-10 m long.
    const Transform tilted(alongX * Rotation(1e-4, SimTK::YAxis), Vec3(0.01, 0.005, 0.024));
    const ContactPoint lowEnd = findOnlyContact(capsule, tilted, box, Transform());
    EXPECT_NEAR(lowEnd.p_G[0], 0.03, 1e-9);
}

// ---- box vs box -------------------------------------------------------------------------

TEST(ShapeContact, BoxOnBoxFaceContactHasFourVertexContacts) {
    const ContactShape small = ContactShape::box(Vec3(0.01), 0.004);
    const ContactShape big = ContactShape::box(kH);
    // Small cube turned 30 degrees about z, its bottom 1 mm below the big box's top face.
    const Rotation R_GA(SimTK::Pi / 6, SimTK::ZAxis);
    const Transform X_GA(R_GA, Vec3(0.005, 0, 0.02 + 0.01 - 0.001));
    const std::vector<ContactPoint> contacts = findContacts(small, X_GA, big, Transform());
    ASSERT_EQ(contacts.size(), 4u);
    for (const ContactPoint& c : contacts) {
        // Each bottom vertex is 1 mm deep; the contact is halfway up to the top face.
        const Vec3 vertex_A = ~R_GA * (c.p_G - X_GA.p() - Vec3(0, 0, 0.0005));
        EXPECT_NEAR(std::abs(vertex_A[0]), 0.01, 1e-15);
        EXPECT_NEAR(std::abs(vertex_A[1]), 0.01, 1e-15);
        EXPECT_NEAR(vertex_A[2], -0.01, 1e-15);
        expectContact(c, c.p_G, Vec3(0, 0, -1), 0.001, 0.004);
    }
    expectMirrored(small, X_GA, big, Transform());
}

// The separating-axis early exit must never hide an overlap. Oracle: a vertex of one box strictly
// inside the other (by the box inequalities, independent of the contact code) means the boxes
// overlap, so there must be contacts; and boxes whose bounding spheres overlap but that a face
// plane separates have none.
TEST(ShapeContact, BoxPairsWithAVertexInsideAlwaysHaveContactsAndSeparatedPairsNone) {
    std::mt19937 random(11);
    std::uniform_real_distribution<double> unit(-1, 1), size(0.005, 0.04);
    int overlapping = 0, separated = 0;
    for (int trial = 0; trial < 5000; ++trial) {
        const ContactShape a = ContactShape::box(Vec3(size(random), size(random), size(random)));
        const ContactShape b = ContactShape::box(Vec3(size(random), size(random), size(random)));
        const Rotation R_GA(Vec3(unit(random), unit(random), unit(random)).norm() * SimTK::Pi,
                            UnitVec3(unit(random), unit(random), unit(random) + 1e-3));
        const Transform X_GA(R_GA, 0.06 * Vec3(unit(random), unit(random), unit(random)));
        const std::vector<ContactPoint> contacts = findContacts(a, X_GA, b, Transform());
        bool vertexInside = false, faceSeparates = false;
        for (int i = 0; i < 8; ++i) {
            const Vec3 v = X_GA * Vec3(i & 1 ? a.halfLengths[0] : -a.halfLengths[0],
                                       i & 2 ? a.halfLengths[1] : -a.halfLengths[1],
                                       i & 4 ? a.halfLengths[2] : -a.halfLengths[2]);
            vertexInside = vertexInside || (std::abs(v[0]) < b.halfLengths[0] && std::abs(v[1]) < b.halfLengths[1] &&
                                            std::abs(v[2]) < b.halfLengths[2]);
        }
        for (int axis = 0; axis < 3; ++axis) {
            bool allAbove = true, allBelow = true;  // every vertex of a beyond one face plane of b
            for (int i = 0; i < 8; ++i) {
                const Vec3 v = X_GA * Vec3(i & 1 ? a.halfLengths[0] : -a.halfLengths[0],
                                           i & 2 ? a.halfLengths[1] : -a.halfLengths[1],
                                           i & 4 ? a.halfLengths[2] : -a.halfLengths[2]);
                allAbove = allAbove && v[axis] > b.halfLengths[axis];
                allBelow = allBelow && v[axis] < -b.halfLengths[axis];
            }
            faceSeparates = faceSeparates || allAbove || allBelow;
        }
        if (vertexInside) {
            ++overlapping;
            EXPECT_FALSE(contacts.empty()) << "trial " << trial << ": a vertex of A is inside B";
        }
        if (faceSeparates) {
            ++separated;
            EXPECT_TRUE(contacts.empty()) << "trial " << trial << ": a face plane of B separates the boxes";
        }
    }
    EXPECT_GT(overlapping, 100);
    EXPECT_GT(separated, 100);
}

TEST(ShapeContact, BoxEdgeCrossingBoxEdgeGivesOneExactEdgeEdgeContact) {
    // B: 40 mm cube, its vertical edge at x = y = 0.02. A: a long bar whose edge runs along
    // (1, -1, 0)/sqrt 2 in the plane z = 0, delta inside B's edge along x and y, with A's two
    // faces at that edge turned toward B (their normals' bisector is -w, w = (1, 1, 0)/sqrt 2).
    const ContactShape b = ContactShape::box(Vec3(0.02), 0.004);
    const ContactShape a = ContactShape::box(Vec3(0.05, 0.01, 0.01), 0.006);
    const double delta = 0.001;
    const Vec3 w = Vec3(1, 1, 0) / kSqrt2, z(0, 0, 1);
    const Vec3 xA = Vec3(1, -1, 0) / kSqrt2, yA = (w + z) / kSqrt2, zA = (z - w) / kSqrt2;
    const Rotation R_GA(SimTK::Mat33(xA[0], yA[0], zA[0], xA[1], yA[1], zA[1], xA[2], yA[2], zA[2]),
                        true);
    const Vec3 edgePoint(0.02 - delta, 0.02 - delta, 0);  // on A's edge (y_A = -h, z_A = +h)
    const Transform X_GA(R_GA, edgePoint + 0.01 * yA - 0.01 * zA);
    // Lines at w-distance delta sqrt 2 apart; closest points edgePoint and (0.02, 0.02, 0).
    expectContact(findOnlyContact(a, X_GA, b, Transform()),
                  Vec3(0.02 - delta / 2, 0.02 - delta / 2, 0), -w, delta * kSqrt2,
                  0.006 * 0.004 / 0.010, 1e-10);
    expectMirrored(a, X_GA, b, Transform());
}

// ---- half-space -------------------------------------------------------------------------

TEST(ShapeContact, SphereAndCapsuleOnHalfSpace) {
    const ContactShape floor = ContactShape::halfSpace();
    // Sphere of radius 20 mm, centre 15 mm above a y-up floor: depth 5 mm, midpoint y = -2.5 mm.
    const ContactShape sphere = ContactShape::sphere(0.02);
    expectContact(findOnlyContact(sphere, Transform(Vec3(0.3, 0.015, -0.1)), floor, kFloor),
                  Vec3(0.3, -0.0025, -0.1), Vec3(0, -1, 0), 0.005, 0.02, 1e-15);
    // Capsule lying along x: contact at the middle of its axis.
    const ContactShape capsule = ContactShape::capsule(0.01, 0.06);
    const Transform lying(Rotation(SimTK::Pi / 2, SimTK::YAxis), Vec3(0.1, 0.008, 0));
    expectContact(findOnlyContact(floor, kFloor, capsule, lying), Vec3(0.1, -0.001, 0),
                  Vec3(0, 1, 0), 0.002, 0.01, 1e-15);
    // Capsule tilted 0.1 rad in the vertical plane: only its lower end touches.
    const Transform tilted(Rotation(SimTK::Pi / 2, SimTK::YAxis) * Rotation(-0.1, SimTK::XAxis),
                           Vec3(0.1, 0.008, 0));
    const Vec3 endPlus = tilted * Vec3(0, 0, 0.03), endMinus = tilted * Vec3(0, 0, -0.03);
    const Vec3 lowEnd = endPlus[1] < endMinus[1] ? endPlus : endMinus;
    ASSERT_NEAR(lowEnd[1], 0.008 - 0.03 * std::sin(0.1), 1e-15);
    // Floor surface point y = 0, capsule surface point y = lowEnd - r: midpoint (y - r) / 2.
    expectContact(findOnlyContact(capsule, tilted, floor, kFloor),
                  Vec3(lowEnd[0], 0.5 * (lowEnd[1] - 0.01), lowEnd[2]), Vec3(0, -1, 0),
                  0.01 - lowEnd[1], 0.01, 1e-15);
    expectMirrored(capsule, tilted, floor, kFloor);
}

TEST(ShapeContact, BoxOnHalfSpaceTouchesWithItsLowVertices) {
    const ContactShape floor = ContactShape::halfSpace();
    // Box resting flat 1 mm deep: its four bottom vertices; tipped on an edge: two.
    const ContactShape box = ContactShape::box(Vec3(0.02, 0.01, 0.03));
    const std::vector<ContactPoint> flat =
        findContacts(box, Transform(Vec3(0, 0.009, 0)), floor, kFloor);
    ASSERT_EQ(flat.size(), 4u);
    for (const ContactPoint& c : flat) {
        EXPECT_NEAR(c.p_G[1], -0.0005, 1e-15);
        expectContact(c, c.p_G, Vec3(0, -1, 0), 0.001, kDefaultBoxCornerRadius, 1e-15);
    }
    // Turned 45 degrees about z, its lowest edge (along z) is (hx + hy) / sqrt 2 below the
    // centre; sunk 1 mm, that edge's two vertices touch.
    const Transform onEdge(Rotation(SimTK::Pi / 4, SimTK::ZAxis),
                           Vec3(0, (0.02 + 0.01) / kSqrt2 - 0.001, 0));
    const std::vector<ContactPoint> edge = findContacts(box, onEdge, floor, kFloor);
    ASSERT_EQ(edge.size(), 2u);
    EXPECT_NEAR(std::abs(edge[0].p_G[2]), 0.03, 1e-15);
    for (const ContactPoint& c : edge) {
        EXPECT_NEAR(c.p_G[1], -0.0005, 1e-15);
        EXPECT_NEAR(c.depth, 0.001, 1e-15);
    }
    expectMirrored(box, onEdge, floor, kFloor);
}

TEST(ShapeContact, TwoHalfSpacesAreRejected) {
    EXPECT_THROW(
        findContacts(ContactShape::halfSpace(), Transform(), ContactShape::halfSpace(), kFloor),
        InputError);
}

TEST(ShapeContact, ModelGeometryOverloadUsesTheGivenPoses) {
    model::Geometry capsule;
    capsule.type = model::Geometry::Type::Capsule;
    capsule.name = "phalanx";
    capsule.radius = 0.01;
    capsule.length = 0.04;
    capsule.X_BG = model::Transform::translation({1, 2, 3});  // ignored: X_GA is given
    model::Geometry sphere;
    sphere.type = model::Geometry::Type::Sphere;
    sphere.name = "ball";
    sphere.radius = 0.02;
    const std::vector<ContactPoint> contacts =
        findContacts(capsule, Transform(), sphere, Transform(Vec3(0.025, 0, 0)));
    ASSERT_EQ(contacts.size(), 1u);
    EXPECT_NEAR(contacts[0].depth, 0.005, 1e-15);
    // A cylinder of the capsule's radius and length: its side is where the capsule's is.
    model::Geometry cylinder = capsule;
    cylinder.type = model::Geometry::Type::Cylinder;
    const std::vector<ContactPoint> cylinderContacts =
        findContacts(cylinder, Transform(), sphere, Transform(Vec3(0.025, 0, 0)));
    ASSERT_EQ(cylinderContacts.size(), 1u);
    EXPECT_NEAR(cylinderContacts[0].depth, 0.005, 1e-15);
    model::Geometry mesh = capsule;
    mesh.type = model::Geometry::Type::Mesh;
    mesh.meshFile = "phalanx.obj";
    try {
        findContacts(mesh, Transform(), sphere, Transform());
        FAIL() << "mesh without triangles accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("geometry 'phalanx': mesh 'phalanx.obj' has no loaded"),
                  std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace graspsim::contact
