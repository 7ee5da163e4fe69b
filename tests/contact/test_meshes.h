#pragma once
// Triangle meshes built in code for the contact tests: a box (12 triangles) and a cylinder
// tessellated into n side facets, outward counter-clockwise triangles, in the geometry frame.

#include <cmath>
#include <memory>

#include "graspsim/contact/contact_shape.h"
#include "graspsim/model/model_description.h"

namespace graspsim::contact::test {

/// The box |x_i| <= h_i as 12 triangles; each face repeats its 4 corners (as an STL file would).
inline model::TriangleMesh makeBoxMesh(const SimTK::Vec3& h) {
    model::TriangleMesh mesh;
    for (int axis = 0; axis < 3; ++axis) {
        for (int sign = -1; sign <= 1; sign += 2) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            const double su[4] = {-1, 1, 1, -1}, sv[4] = {-1, -1, 1, 1};
            const int first = static_cast<int>(mesh.vertices.size());
            for (int k = 0; k < 4; ++k) {
                model::Vec3 p{0, 0, 0};
                p[axis] = sign * h[axis];
                p[u] = su[k] * h[u];
                p[v] = sv[k] * h[v];
                mesh.vertices.push_back(p);
            }
            // (u, v, axis) is right-handed: the corner order is counter-clockwise seen from +axis.
            if (sign > 0) {
                mesh.triangles.push_back({first, first + 1, first + 2});
                mesh.triangles.push_back({first, first + 2, first + 3});
            } else {
                mesh.triangles.push_back({first, first + 2, first + 1});
                mesh.triangles.push_back({first, first + 3, first + 2});
            }
        }
    }
    return mesh;
}

/// The cylinder inscribed in radius r, length L along z, with n side facets (fan caps).
inline model::TriangleMesh makeCylinderMesh(double r, double length, int n) {
    model::TriangleMesh mesh;
    const double half = 0.5 * length;
    for (int k = 0; k < n; ++k) {
        const double angle = 2 * SimTK::Pi * k / n;
        mesh.vertices.push_back({r * std::cos(angle), r * std::sin(angle), -half});  // 2k
        mesh.vertices.push_back({r * std::cos(angle), r * std::sin(angle), half});   // 2k + 1
    }
    const int bottom = 2 * n, top = 2 * n + 1;
    mesh.vertices.push_back({0, 0, -half});
    mesh.vertices.push_back({0, 0, half});
    for (int k = 0; k < n; ++k) {
        const int b0 = 2 * k, t0 = 2 * k + 1, b1 = 2 * ((k + 1) % n), t1 = b1 + 1;
        mesh.triangles.push_back({b0, b1, t1});
        mesh.triangles.push_back({b0, t1, t0});
        mesh.triangles.push_back({top, t0, t1});
        mesh.triangles.push_back({bottom, b1, b0});
    }
    return mesh;
}

/// A ConvexMesh shape of a triangle mesh.
inline ContactShape makeMeshShape(const model::TriangleMesh& mesh) {
    return ContactShape::convexMesh(ConvexPolytope::build(mesh, "test mesh"));
}

}  // namespace graspsim::contact::test
