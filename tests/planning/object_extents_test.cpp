// The object's extents and its smooth stand-in (src/planning/object_extents.h). Oracles: the
// closed-form extents of a box, an ellipsoid and a mesh of a box moved off its frame's origin
// (its vertices give them), and the box's inscribed ellipsoid.

#include "object_extents.h"

#include "graspsim/contact/convex_polytope.h"
#include "graspsim/error.h"

#include <gtest/gtest.h>

using namespace graspsim;
using namespace graspsim::planning;

namespace {

// The box of half-lengths h centred at c, as a closed, outward-facing mesh (8 vertices, 12
// triangles; vertex i has the sign bits (x, y, z) = (i & 4, i & 2, i & 1)).
model::TriangleMesh makeBoxMesh(const SimTK::Vec3& h, const SimTK::Vec3& c) {
    model::TriangleMesh mesh;
    for (int i = 0; i < 8; ++i) {
        mesh.vertices.push_back({c[0] + (i & 4 ? 1 : -1) * h[0], c[1] + (i & 2 ? 1 : -1) * h[1],
                                 c[2] + (i & 1 ? 1 : -1) * h[2]});
    }
    mesh.triangles = {{1, 3, 2}, {1, 2, 0}, {4, 6, 7}, {4, 7, 5}, {0, 4, 5}, {0, 5, 1},
                      {3, 7, 6}, {3, 6, 2}, {2, 6, 4}, {2, 4, 0}, {1, 5, 7}, {1, 7, 3}};
    return mesh;
}

const SimTK::Vec3 kPhone(0.035, 0.07, 0.004);  // half-lengths (m)

}  // namespace

TEST(ObjectExtents, ABoxAndAnEllipsoidGiveTheirHalfLengthsAndSemiAxesAboutTheirCentre) {
    const ObjectExtents box = findObjectExtents(contact::ContactShape::box(kPhone));
    const ObjectExtents ellipsoid = findObjectExtents(contact::ContactShape::ellipsoid(kPhone));
    EXPECT_EQ(box.halfExtents, kPhone);
    EXPECT_EQ(ellipsoid.halfExtents, kPhone);
    EXPECT_EQ(box.centre_S, SimTK::Vec3(0));
    EXPECT_EQ(findObjectExtents(contact::ContactShape::sphere(0.02)).halfExtents, SimTK::Vec3(0));
    EXPECT_NEAR(calcObjectWidth(contact::ContactShape::box(kPhone)), 0.008, 1e-6);
}

// A mesh of the phone 10, -20 and 3 mm off its frame's origin: its extents are the box's, centred
// where the box is (to the support error of the far points, below 1e-4 m; measured here exactly
// to round-off, the far points' nearest points lying on the faces).
TEST(ObjectExtents, AMeshOffItsFrameOriginHasTheExtentsOfItsVertices) {
    const SimTK::Vec3 centre(0.01, -0.02, 0.003);
    const auto polytope = contact::ConvexPolytope::build(makeBoxMesh(kPhone, centre), "moved box mesh");
    const ObjectExtents mesh = findObjectExtents(contact::ContactShape::convexMesh(polytope));
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(mesh.halfExtents[k], kPhone[k], 1e-9) << k;
        EXPECT_NEAR(mesh.centre_S[k], centre[k], 1e-9) << k;
    }
}

// The stand-in of a box is its inscribed ellipsoid (semi-axes its half-lengths, at its centre);
// of a moved mesh of it, the same ellipsoid at the mesh's centre. Spheres, capsules, cylinders and
// ellipsoids have no edges and no stand-in.
TEST(ObjectExtents, AShapeWithEdgesStandsInAsTheEllipsoidOfItsExtents) {
    const SmoothStandIn box = findSmoothStandIn(contact::ContactShape::box(kPhone));
    EXPECT_EQ(box.shape.type, contact::ContactShape::Type::Ellipsoid);
    EXPECT_EQ(box.shape.semiAxes, kPhone);
    EXPECT_EQ(box.X_SE.p(), SimTK::Vec3(0));
    const SimTK::Vec3 centre(0.01, -0.02, 0.003);
    const auto polytope = contact::ConvexPolytope::build(makeBoxMesh(kPhone, centre), "moved box mesh");
    const contact::ContactShape meshShape = contact::ContactShape::convexMesh(polytope);
    EXPECT_TRUE(hasEdges(meshShape));
    const SmoothStandIn mesh = findSmoothStandIn(meshShape);
    EXPECT_LT((mesh.shape.semiAxes - kPhone).norm(), 1e-9);
    EXPECT_LT((mesh.X_SE.p() - centre).norm(), 1e-9);

    for (const contact::ContactShape& smooth : {contact::ContactShape::sphere(0.02), contact::ContactShape::capsule(0.01, 0.05),
                                                contact::ContactShape::cylinder(0.02, 0.1),
                                                contact::ContactShape::ellipsoid(kPhone)}) {
        EXPECT_FALSE(hasEdges(smooth));
    }
    try {
        findSmoothStandIn(contact::ContactShape::sphere(0.02));
        FAIL() << "a sphere has no stand-in";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("no smooth stand-in for an object of half-extents"), std::string::npos) << e.what();
    }
}
