#include "graspsim/contact/convex_polytope.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "graspsim/error.h"
#include "test_meshes.h"

namespace graspsim::contact {
namespace {

using SimTK::Vec3;

const Vec3 kHalf(0.03, 0.02, 0.01);

// The message of the InputError that building `mesh` throws ("" if none).
std::string findBuildError(const model::TriangleMesh& mesh) {
    try {
        ConvexPolytope::build(mesh, "geometry 'part'");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(ConvexPolytope, BoxMeshHasTheBoxFacesEdgesAndVertices) {
    const auto box = ConvexPolytope::build(test::makeBoxMesh(kHalf), "box");
    EXPECT_EQ(box->getFaces().size(), 6u);
    EXPECT_EQ(box->getEdges().size(), 12u);  // the face diagonals are not edges
    EXPECT_EQ(box->getVertices().size(), 8u);
    EXPECT_EQ(box->getTriangles().size(), 12u);
    EXPECT_NEAR(box->getBoundingRadius(), kHalf.norm(), 1e-15);
    for (const ConvexPolytope::Face& f : box->getFaces()) {
        // Oracle: a box face's plane is |x_i| = h_i with the axis normal.
        int axis = 0;
        for (int i = 0; i < 3; ++i) {
            if (std::abs(f.normal[i]) > 0.5) axis = i;
        }
        EXPECT_EQ(std::abs(f.normal[axis]), 1.0);
        EXPECT_NEAR(f.offset, kHalf[axis], 1e-15);
    }
}

TEST(ConvexPolytope, CylinderMeshMergesCapsAndSideQuads) {
    const auto cylinder = ConvexPolytope::build(test::makeCylinderMesh(0.03, 0.1, 16), "cyl");
    EXPECT_EQ(cylinder->getFaces().size(), 18u);      // 16 sides and 2 caps
    EXPECT_EQ(cylinder->getEdges().size(), 48u);      // 16 vertical, 32 on the rims
    EXPECT_EQ(cylinder->getVertices().size(), 32u);   // the cap centres are not corners
}

TEST(ConvexPolytope, SignedDistanceEqualsTheBoxOnes) {
    const auto box = ConvexPolytope::build(test::makeBoxMesh(kHalf), "box");
    std::mt19937 random(3);
    std::uniform_real_distribution<double> coordinate(-0.05, 0.05);
    for (int i = 0; i < 500; ++i) {
        const Vec3 p(coordinate(random), coordinate(random), coordinate(random));
        // Oracle: the box's closed-form SDF (Euclidean outside, nearest face depth inside).
        Vec3 outside(0);
        double deepest = -SimTK::Infinity;
        for (int k = 0; k < 3; ++k) {
            const double q = std::abs(p[k]) - kHalf[k];
            outside[k] = std::max(q, 0.0);
            deepest = std::max(deepest, q);
        }
        const double expected = deepest > 0 ? outside.norm() : deepest;
        EXPECT_NEAR(box->calcSignedDistance(p), expected, 1e-15) << p;
        EXPECT_NEAR(box->findSurface(p).distance, expected, 1e-15) << p;
    }
}

// A triangular prism (an equilateral triangle extruded along z): on its axis the three sides
// are equally deep and their normals cancel; the normal is then the first face's, not NaN.
TEST(ConvexPolytope, CancellingTiedNormalsFallBackToTheFirstFace) {
    model::TriangleMesh prism;
    for (int k = 0; k < 3; ++k) {
        const double a = 2 * SimTK::Pi * k / 3;
        prism.vertices.push_back({0.02 * std::cos(a), 0.02 * std::sin(a), -0.05});
        prism.vertices.push_back({0.02 * std::cos(a), 0.02 * std::sin(a), 0.05});
    }
    for (int k = 0; k < 3; ++k) {
        const int b0 = 2 * k, t0 = b0 + 1, b1 = 2 * ((k + 1) % 3), t1 = b1 + 1;
        prism.triangles.push_back({b0, b1, t1});
        prism.triangles.push_back({b0, t1, t0});
    }
    prism.triangles.push_back({1, 3, 5});
    prism.triangles.push_back({0, 4, 2});
    const auto polytope = ConvexPolytope::build(prism, "prism");
    EXPECT_EQ(polytope->getFaces().size(), 5u);
    const ConvexPolytope::Surface s = polytope->findSurface(Vec3(0, 0, 0.001));
    // Oracle: the inradius of the triangle, r cos 60 deg = 0.01 m.
    EXPECT_NEAR(s.distance, -0.01, 1e-15);
    EXPECT_TRUE(s.n_S.isFinite());
    EXPECT_NEAR(s.n_S.norm(), 1, 1e-15);
}

TEST(ConvexPolytope, BadMeshesAreRejectedNamingTheProblem) {
    model::TriangleMesh open = test::makeBoxMesh(kHalf);
    open.triangles.pop_back();
    EXPECT_NE(findBuildError(open).find("geometry 'part': mesh is not closed"), std::string::npos)
        << findBuildError(open);

    model::TriangleMesh inverted = test::makeBoxMesh(kHalf);
    for (auto& t : inverted.triangles) std::swap(t[1], t[2]);
    EXPECT_NE(findBuildError(inverted).find("normals inverted"), std::string::npos)
        << findBuildError(inverted);

    model::TriangleMesh flipped = test::makeBoxMesh(kHalf);
    std::swap(flipped.triangles[0][1], flipped.triangles[0][2]);
    EXPECT_NE(findBuildError(flipped).find("not consistently oriented"), std::string::npos)
        << findBuildError(flipped);

    // A dent: one corner of the cylinder's rim pushed toward the axis.
    model::TriangleMesh dented = test::makeCylinderMesh(0.03, 0.1, 16);
    dented.vertices[4][0] *= 0.5;
    dented.vertices[4][1] *= 0.5;
    EXPECT_NE(findBuildError(dented).find("is not convex"), std::string::npos)
        << findBuildError(dented);

    model::TriangleMesh outOfRange = test::makeBoxMesh(kHalf);
    outOfRange.triangles[3][2] = 99;
    EXPECT_NE(findBuildError(outOfRange).find("vertex index 99 out of range"), std::string::npos);

    model::TriangleMesh tiny;
    tiny.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    tiny.triangles = {{0, 1, 2}};
    EXPECT_NE(findBuildError(tiny).find("needs at least 4"), std::string::npos);
}

TEST(ConvexPolytope, ContactShapeFromAMeshGeometry) {
    model::Geometry geometry;
    geometry.type = model::Geometry::Type::Mesh;
    geometry.name = "phone";
    geometry.meshFile = "phone.stl";
    EXPECT_THROW(ContactShape::fromGeometry(geometry), InputError);  // not loaded
    geometry.mesh = std::make_shared<model::TriangleMesh>(test::makeBoxMesh(kHalf));
    const ContactShape shape = ContactShape::fromGeometry(geometry);
    EXPECT_EQ(shape.type, ContactShape::Type::ConvexMesh);
    EXPECT_NEAR(shape.calcBoundingRadius(), kHalf.norm(), 1e-15);
    const ContactShape copy = shape;  // shares the polytope
    EXPECT_EQ(copy.polytope.get(), shape.polytope.get());
}

}  // namespace
}  // namespace graspsim::contact
