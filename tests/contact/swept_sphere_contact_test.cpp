// Where a capsule touches a solid under CapsuleContact::Ends, against closed forms, and that its
// force and moment stay continuous as it tilts through lying flat, where the Deepest rule jumps.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "graspsim/contact/shape_contact.h"

namespace graspsim::contact {
namespace {

using SimTK::Rotation;
using SimTK::Transform;
using SimTK::Vec3;

const double kRadius = 0.005, kLength = 0.04;
// A box whose top face is z = 0.02 and whose side face x = 0.05 meets it along an edge.
const ContactShape kBox = ContactShape::box(Vec3(0.05, 0.03, 0.02));
const Rotation kAlongX(SimTK::Pi / 2, SimTK::YAxis);

std::vector<ContactPoint> findCapsuleContacts(const Transform& X_GA, const ContactShape& solid, const Transform& X_GB,
                                              CapsuleContact rule) {
    std::vector<ContactPoint> contacts;
    appendContacts(ContactShape::capsule(kRadius, kLength), X_GA, solid, X_GB, contacts, rule);
    return contacts;
}

// The contacts of a capsule of kRadius whose core runs from p0 to p1 (in Ground) with the box.
std::vector<ContactPoint> findCoreContacts(const Vec3& p0, const Vec3& p1, CapsuleContact rule) {
    std::vector<ContactPoint> contacts;
    const Transform X_GA(Rotation(SimTK::UnitVec3(p1 - p0), SimTK::ZAxis), 0.5 * (p0 + p1));
    appendContacts(ContactShape::capsule(kRadius, (p1 - p0).norm()), X_GA, kBox, Transform(), contacts, rule);
    return contacts;
}

// A capsule of kLength centred at `centre` with its core turned from x by `angle` about -y (its
// x = +L/2 end rising for angle > 0), and that end's and the other's positions.
struct TiltedCore {
    Transform X_GA;
    Vec3 p0, p1;
};

TiltedCore tiltCore(const Vec3& centre, double angle) {
    const Vec3 half = (kLength / 2) * Vec3(std::cos(angle), 0, std::sin(angle));
    return {Transform(kAlongX * Rotation(-angle, SimTK::YAxis), centre), centre - half, centre + half};
}

void expectPointNear(const Vec3& actual, const Vec3& expected, double tolerance) {
    EXPECT_LE((actual - expected).norm(), tolerance) << "got " << actual << ", expected " << expected;
}

TEST(CapsuleEndContacts, FlatOnABoxFaceTouchesAtBothEndsWithTheirDepths) {
    // Core x in [-0.01, 0.03] at z = 0.024: 1 mm deep all along. Surface points z = 0.02 and
    // 0.024 - 0.005, midway 0.0195.
    const Transform onFace(kAlongX, Vec3(0.01, 0.005, 0.024));
    const std::vector<ContactPoint> ends = findCapsuleContacts(onFace, kBox, Transform(), CapsuleContact::Ends);
    ASSERT_EQ(ends.size(), 2u);
    std::vector<double> xs{ends[0].p_G[0], ends[1].p_G[0]};
    std::sort(xs.begin(), xs.end());
    EXPECT_NEAR(xs[0], -0.01, 1e-12);
    EXPECT_NEAR(xs[1], 0.03, 1e-12);
    for (const ContactPoint& c : ends) {
        EXPECT_NEAR(c.depth, 0.001, 1e-12);
        EXPECT_NEAR(c.p_G[2], 0.0195, 1e-12);
        EXPECT_NEAR(c.n_G[2], -1, 1e-12);
        EXPECT_EQ(c.radius, kRadius);
    }
    // The deepest rule touches once, mid-axis, as before.
    const std::vector<ContactPoint> deepest = findCapsuleContacts(onFace, kBox, Transform(), CapsuleContact::Deepest);
    ASSERT_EQ(deepest.size(), 1u);
    EXPECT_NEAR(deepest[0].p_G[0], 0.01, 1e-9);
}

TEST(CapsuleEndContacts, TiltedOnAHalfSpaceEachEndHasItsOwnDepth) {
    // Half-space z <= 0 (S = G). Each end at height h within the radius has depth r - h and its
    // point at z = (h - r) / 2, below the end.
    const TiltedCore core = tiltCore(Vec3(0, 0, 0.00425), 0.0125);
    ASSERT_NEAR(core.p1[2] - core.p0[2], 0.0005, 1e-6);
    const std::vector<ContactPoint> both =
        findCapsuleContacts(core.X_GA, ContactShape::halfSpace(), Transform(), CapsuleContact::Ends);
    ASSERT_EQ(both.size(), 2u);
    int k = 0;
    for (const Vec3& end : {core.p0, core.p1}) {
        EXPECT_NEAR(both[k].depth, kRadius - end[2], 1e-12);
        expectPointNear(both[k].p_G, Vec3(end[0], 0, 0.5 * (end[2] - kRadius)), 1e-12);
        EXPECT_NEAR(both[k].n_G[2], -1, 1e-12);
        ++k;
    }
    // The upper end out of reach: only the lower end, the deepest rule's contact.
    for (const double angle : {0.06, 0.1}) {
        const TiltedCore steep = tiltCore(Vec3(0, 0, 0.004), angle);
        ASSERT_GT(steep.p1[2], kRadius);
        const std::vector<ContactPoint> ends =
            findCapsuleContacts(steep.X_GA, ContactShape::halfSpace(), Transform(), CapsuleContact::Ends);
        const std::vector<ContactPoint> deepest =
            findCapsuleContacts(steep.X_GA, ContactShape::halfSpace(), Transform(), CapsuleContact::Deepest);
        ASSERT_EQ(ends.size(), 1u);
        ASSERT_EQ(deepest.size(), 1u);
        EXPECT_NEAR(ends[0].depth, kRadius - steep.p0[2], 1e-12);
        EXPECT_NEAR(ends[0].depth, deepest[0].depth, 1e-15);
        expectPointNear(ends[0].p_G, deepest[0].p_G, 1e-15);
    }
}

TEST(CapsuleEndContacts, AnEdgeAcrossTheCapsuleKeepsItsContactLessTheDeeperEndsDepth) {
    // Core from (0.045, 0, 0.030) to (0.065, 0, 0.010) passes 0.005/sqrt 2 from the box's edge
    // (x = 0.05, z = 0.02); both ends are farther than the radius: one interior contact, the
    // deepest rule's.
    const std::vector<ContactPoint> interior =
        findCoreContacts(Vec3(0.045, 0, 0.030), Vec3(0.065, 0, 0.010), CapsuleContact::Ends);
    ASSERT_EQ(interior.size(), 1u);
    EXPECT_NEAR(interior[0].depth, kRadius - 0.005 / std::sqrt(2.0), 1e-10);
    // Core from (0.04, 0, 0.0235) down at slope -1/2: its end 3.5 mm above the top face (depth
    // 1.5 mm), and inside the box's corner for x in [0.047, 0.05], 1 mm deep at x = 0.049
    // (depth 6 mm under the deepest rule). Ends: the end's 1.5 mm and the interior's 6 - 1.5 mm.
    const Vec3 p0(0.04, 0, 0.0235), p1(0.07, 0, 0.0085);
    const std::vector<ContactPoint> deepest = findCoreContacts(p0, p1, CapsuleContact::Deepest);
    ASSERT_EQ(deepest.size(), 1u);
    EXPECT_NEAR(deepest[0].depth, 0.006, 1e-9);
    const std::vector<ContactPoint> ends = findCoreContacts(p0, p1, CapsuleContact::Ends);
    ASSERT_EQ(ends.size(), 2u);
    EXPECT_NEAR(ends[0].depth, 0.0015, 1e-12);
    EXPECT_NEAR(ends[0].p_G[0], 0.04, 1e-12);
    EXPECT_NEAR(ends[1].depth, 0.0045, 1e-9);
    EXPECT_NEAR(ends[1].p_G[0], deepest[0].p_G[0], 1e-12);
}

TEST(CapsuleEndContacts, ParallelOnACylindersSideTouchesAtBothEndsWithTheCombinedRadius) {
    // A cylinder of radius 0.03 along x (its S z turned onto x); the core 4 mm above its top
    // line: depth 1 mm at each end, Hertz radius 1 / (1/0.005 + 1/0.03).
    const ContactShape cylinder = ContactShape::cylinder(0.03, 0.1);
    const Transform onSide(kAlongX, Vec3(0, 0, 0.034));
    const std::vector<ContactPoint> ends =
        findCapsuleContacts(onSide, cylinder, Transform(kAlongX, Vec3(0)), CapsuleContact::Ends);
    ASSERT_EQ(ends.size(), 2u);
    for (const ContactPoint& c : ends) {
        EXPECT_NEAR(c.depth, 0.001, 1e-12);
        EXPECT_NEAR(std::abs(c.p_G[0]), 0.02, 1e-12);
        EXPECT_NEAR(c.radius, 1 / (1 / 0.005 + 1 / 0.03), 1e-15);
    }
}

// The Hertz-weighted normal force sum d^1.5 and its moment about the core's centre.
struct ForceAndMoment {
    double force = 0;
    Vec3 moment{0};
};

ForceAndMoment calcHertzResultant(const std::vector<ContactPoint>& contacts, const Vec3& centre) {
    ForceAndMoment sum;
    for (const ContactPoint& c : contacts) {
        const double f = std::pow(c.depth, 1.5);
        sum.force += f;
        sum.moment += SimTK::cross(c.p_G - centre, f * c.n_G.asVec3());
    }
    return sum;
}

// The largest change of moment between successive tilts, in steps of dTheta through lying flat
// 1 mm deep on the box's top face.
double findLargestMomentStep(CapsuleContact rule, double dTheta) {
    const Vec3 centre(0.01, 0.005, 0.024);
    double largest = 0;
    ForceAndMoment previous;
    for (int k = -100; k <= 100; ++k) {
        const Transform X_GA(kAlongX * Rotation(k * dTheta, SimTK::YAxis), centre);
        const ForceAndMoment now = calcHertzResultant(findCapsuleContacts(X_GA, kBox, Transform(), rule), centre);
        if (k > -100) largest = std::max(largest, (now.moment - previous.moment).norm());
        previous = now;
    }
    return largest;
}

TEST(CapsuleEndContacts, ForceAndMomentAreContinuousThroughLyingFlat) {
    const double dTheta = 1e-5, depth = 0.001, halfLength = kLength / 2;
    // Per step each end's depth changes by halfLength dTheta, its d^1.5 by 1.5 sqrt(d) times
    // that, on an arm of halfLength: a bound for both ends, doubled for the arm's own turn and
    // the depth's growth over the sweep.
    const double bound = 2 * 2 * 1.5 * std::sqrt(1.1 * depth) * halfLength * dTheta * halfLength;
    EXPECT_LT(findLargestMomentStep(CapsuleContact::Ends, dTheta), bound);
    // The deepest rule jumps by the whole d^1.5 moved over the half-length.
    EXPECT_GT(findLargestMomentStep(CapsuleContact::Deepest, dTheta), 0.5 * std::pow(depth, 1.5) * halfLength);
}

}  // namespace
}  // namespace graspsim::contact
