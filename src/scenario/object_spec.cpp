#include "graspsim/scenario/scenario.h"

#include "graspsim/model/object_model.h"
#include "graspsim/model/triangle_mesh.h"

#include <algorithm>
#include <cmath>

namespace graspsim::scenario {

namespace {

// Signed distance to a solid of revolution about z, given the signed radial and axial
// distances to its side and end faces: outside, the Euclidean distance to the rim region;
// inside, minus the distance to the nearer face.
double combineAxialDistances(double radial, double axial) {
    if (radial <= 0 && axial <= 0) return std::max(radial, axial);
    return std::hypot(std::max(radial, 0.0), std::max(axial, 0.0));
}

Vec3 normalize(const Vec3& v) {
    const double n = std::hypot(v[0], v[1], v[2]);
    return n > 0 ? Vec3{v[0] / n, v[1] / n, v[2] / n} : Vec3{0, 0, 1};
}

// Point on the capsule's axis segment nearest to P.
Vec3 findNearestAxisPoint(const Vec3& p, double length) {
    return {0, 0, std::clamp(p[2], -length / 2, length / 2)};
}

double calcBoxDistance(const Vec3& size, const Vec3& p_OP) {
    double outside = 0, inside = -INFINITY;
    for (int i = 0; i < 3; ++i) {
        const double d = std::abs(p_OP[i]) - size[i] / 2;
        outside += d > 0 ? d * d : 0;
        inside = std::max(inside, d);
    }
    return inside > 0 ? std::sqrt(outside) : inside;
}

double calcEllipsoidDistance(const Vec3& a, const Vec3& p) {
    // F = sum (x_i/a_i)^2 - 1 vanishes on the surface; F / |grad F| is its first-order distance.
    double F = -1;
    Vec3 gradient{};
    for (int i = 0; i < 3; ++i) {
        F += p[i] * p[i] / (a[i] * a[i]);
        gradient[i] = 2 * p[i] / (a[i] * a[i]);
    }
    const double g = std::hypot(gradient[0], gradient[1], gradient[2]);
    return g > 0 ? F / g : -std::min({a[0], a[1], a[2]});
}

}  // namespace

std::string toString(ObjectShape shape) {
    switch (shape) {
        case ObjectShape::Sphere: return "sphere";
        case ObjectShape::Box: return "box";
        case ObjectShape::Cylinder: return "cylinder";
        case ObjectShape::Capsule: return "capsule";
        case ObjectShape::Ellipsoid: return "ellipsoid";
        case ObjectShape::Mesh: return "mesh";
    }
    return "unknown";
}

model::Transform ObjectSpec::findPose() const {
    // Body-fixed X-Y-Z: rotate about x, then about the new y, then about the newest z, so the
    // rotations compose left to right.
    model::Transform X_GO = model::Transform::axisAngle({1, 0, 0}, orientation[0]) *
                            model::Transform::axisAngle({0, 1, 0}, orientation[1]) *
                            model::Transform::axisAngle({0, 0, 1}, orientation[2]);
    X_GO.p = position;
    return X_GO;
}

Vec3 ObjectSpec::toMeshFrame(const Vec3& p_OP) const {
    return {p_OP[0] + meshCentroid[0], p_OP[1] + meshCentroid[1], p_OP[2] + meshCentroid[2]};
}

double ObjectSpec::calcSurfaceDistance(const Vec3& p) const {
    switch (shape) {
        case ObjectShape::Sphere: return std::hypot(p[0], p[1], p[2]) - radius;
        case ObjectShape::Box: return calcBoxDistance(size, p);
        case ObjectShape::Cylinder:
            return combineAxialDistances(std::hypot(p[0], p[1]) - radius, std::abs(p[2]) - length / 2);
        case ObjectShape::Capsule: {
            const Vec3 c = findNearestAxisPoint(p, length);
            return std::hypot(p[0] - c[0], p[1] - c[1], p[2] - c[2]) - radius;
        }
        case ObjectShape::Ellipsoid: return calcEllipsoidDistance(semiAxes, p);
        case ObjectShape::Mesh: return model::calcConvexMeshDistance(*meshData, toMeshFrame(p));
    }
    return 0;
}

Vec3 ObjectSpec::findOutwardNormal(const Vec3& p) const {
    switch (shape) {
        case ObjectShape::Sphere: return normalize(p);
        case ObjectShape::Box: {
            // The face whose plane is nearest, the same choice calcSurfaceDistance makes inside the box.
            int face = 0;
            for (int i = 1; i < 3; ++i) {
                if (std::abs(p[i]) - size[i] / 2 > std::abs(p[face]) - size[face] / 2) face = i;
            }
            Vec3 n{0, 0, 0};
            n[face] = p[face] >= 0 ? 1 : -1;
            return n;
        }
        case ObjectShape::Cylinder:
            if (std::abs(p[2]) - length / 2 > std::hypot(p[0], p[1]) - radius) return {0, 0, p[2] >= 0 ? 1.0 : -1.0};
            return normalize({p[0], p[1], 0});
        case ObjectShape::Capsule: {
            const Vec3 c = findNearestAxisPoint(p, length);
            return normalize({p[0] - c[0], p[1] - c[1], p[2] - c[2]});
        }
        case ObjectShape::Ellipsoid:
            return normalize({p[0] / (semiAxes[0] * semiAxes[0]), p[1] / (semiAxes[1] * semiAxes[1]),
                              p[2] / (semiAxes[2] * semiAxes[2])});
        case ObjectShape::Mesh: return model::findConvexMeshNormal(*meshData, toMeshFrame(p));
    }
    return {0, 0, 1};
}

double ObjectSpec::findHalfThickness() const {
    switch (shape) {
        case ObjectShape::Sphere:
        case ObjectShape::Capsule: return radius;
        case ObjectShape::Box: return std::min({size[0], size[1], size[2]}) / 2;
        case ObjectShape::Cylinder: return std::min(radius, length / 2);
        case ObjectShape::Ellipsoid: return std::min({semiAxes[0], semiAxes[1], semiAxes[2]});
        case ObjectShape::Mesh: return -model::calcConvexMeshDistance(*meshData, meshCentroid);
    }
    return 0;
}

namespace {

model::ModelDescription buildShapeModel(const ObjectSpec& object) {
    switch (object.shape) {
        case ObjectShape::Sphere: return model::buildBallModel(object.mass, object.radius);
        case ObjectShape::Box: return model::buildPhoneModel(object.mass, object.size);
        case ObjectShape::Cylinder: return model::buildCylinderModel(object.mass, object.radius, object.length);
        case ObjectShape::Capsule: return model::buildCapsuleModel(object.mass, object.radius, object.length);
        case ObjectShape::Ellipsoid: return model::buildEllipsoidModel(object.mass, object.semiAxes);
        case ObjectShape::Mesh:
            return model::buildMeshModel(object.mass, *object.meshData, object.mesh, object.meshScale);
    }
    return {};
}

}  // namespace

model::ModelDescription buildObjectModel(const ObjectSpec& object) {
    // The builders name their bodies for the thesis's objects ("phone" for any box, "ball" for any
    // sphere) and their geometry after themselves ("mesh_shape"); a scenario's object is none of
    // those but the scenario's `object`, so contacts.csv names it the same way whatever its shape.
    model::ModelDescription model = buildShapeModel(object);
    model::Body& body = model.bodies.at(0);
    model.name = body.name = kObjectBodyName;
    body.geometry.at(0).name = toString(object.shape);
    return model;
}

}  // namespace graspsim::scenario
