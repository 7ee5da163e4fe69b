#include "graspsim/contact/contact_shape.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include "graspsim/error.h"
#include "graspsim/system/simtk_conversion.h"

namespace graspsim::contact {

namespace {

// "<what>: <field> (<value>) must be <accepted>".
[[noreturn]] void throwBadSize(const std::string& what, const std::string& field, double value,
                               const std::string& accepted) {
    std::ostringstream message;
    message << what << ": " << field << " (" << value << ") must be " << accepted;
    throw InputError(message.str());
}

void checkPositive(const std::string& what, const std::string& field, double value) {
    if (!(std::isfinite(value) && value > 0)) {
        throwBadSize(what, field, value, "finite and > 0 (m)");
    }
}

}  // namespace

ContactShape ContactShape::sphere(double radius) {
    ContactShape shape;
    shape.type = Type::Sphere;
    shape.radius = radius;
    return shape;
}

ContactShape ContactShape::capsule(double radius, double length) {
    ContactShape shape;
    shape.type = Type::Capsule;
    shape.radius = radius;
    shape.length = length;
    return shape;
}

ContactShape ContactShape::box(const SimTK::Vec3& halfLengths, double cornerRadius) {
    ContactShape shape;
    shape.type = Type::Box;
    shape.halfLengths = halfLengths;
    shape.cornerRadius = cornerRadius;
    return shape;
}

ContactShape ContactShape::halfSpace() {
    ContactShape shape;
    shape.type = Type::HalfSpace;
    return shape;
}

ContactShape ContactShape::cylinder(double radius, double length, double cornerRadius) {
    ContactShape shape;
    shape.type = Type::Cylinder;
    shape.radius = radius;
    shape.length = length;
    shape.cornerRadius = cornerRadius;
    return shape;
}

ContactShape ContactShape::ellipsoid(const SimTK::Vec3& semiAxes) {
    ContactShape shape;
    shape.type = Type::Ellipsoid;
    shape.semiAxes = semiAxes;
    return shape;
}

ContactShape ContactShape::convexMesh(std::shared_ptr<const ConvexPolytope> polytope,
                                      double cornerRadius) {
    ContactShape shape;
    shape.type = Type::ConvexMesh;
    shape.polytope = std::move(polytope);
    shape.cornerRadius = cornerRadius;
    return shape;
}

ContactShape ContactShape::fromGeometry(const model::Geometry& geometry) {
    const std::string what = "geometry '" + geometry.name + "'";
    ContactShape shape;
    switch (geometry.type) {
        case model::Geometry::Type::Sphere:
            shape = sphere(geometry.radius);
            break;
        case model::Geometry::Type::Capsule:
            shape = capsule(geometry.radius, geometry.length);
            break;
        case model::Geometry::Type::Box: {
            const model::Vec3& h = geometry.halfLengths;
            shape = box(SimTK::Vec3(h[0], h[1], h[2]));
            break;
        }
        case model::Geometry::Type::Cylinder:
            shape = cylinder(geometry.radius, geometry.length);
            break;
        case model::Geometry::Type::Ellipsoid: {
            const model::Vec3& e = geometry.semiAxes;
            shape = ellipsoid(SimTK::Vec3(e[0], e[1], e[2]));
            break;
        }
        case model::Geometry::Type::Mesh:
            if (!geometry.mesh) {
                throw InputError(what + ": mesh '" + geometry.meshFile +
                                 "' has no loaded triangles; contact needs the mesh read from "
                                 "its file");
            }
            shape = convexMesh(ConvexPolytope::build(*geometry.mesh, what));
            break;
    }
    shape.validate(what);
    return shape;
}

void ContactShape::validate(const std::string& what) const {
    switch (type) {
        case Type::Sphere:
            checkPositive(what, "radius", radius);
            break;
        case Type::Capsule:
            checkPositive(what, "radius", radius);
            if (!(std::isfinite(length) && length >= 0)) {
                throwBadSize(what, "length", length, "finite and >= 0 (m)");
            }
            break;
        case Type::Box:
            checkPositive(what, "halfLengths[0]", halfLengths[0]);
            checkPositive(what, "halfLengths[1]", halfLengths[1]);
            checkPositive(what, "halfLengths[2]", halfLengths[2]);
            checkPositive(what, "cornerRadius", cornerRadius);
            break;
        case Type::HalfSpace:
            break;
        case Type::Cylinder:
            checkPositive(what, "radius", radius);
            checkPositive(what, "length", length);
            checkPositive(what, "cornerRadius", cornerRadius);
            break;
        case Type::Ellipsoid:
            checkPositive(what, "semiAxes[0]", semiAxes[0]);
            checkPositive(what, "semiAxes[1]", semiAxes[1]);
            checkPositive(what, "semiAxes[2]", semiAxes[2]);
            break;
        case Type::ConvexMesh:
            if (!polytope) throw InputError(what + ": convex mesh has no polytope");
            checkPositive(what, "cornerRadius", cornerRadius);
            break;
    }
}

double ContactShape::calcBoundingRadius() const {
    switch (type) {
        case Type::Sphere:
            return radius;
        case Type::Capsule:
            return radius + 0.5 * length;
        case Type::Box:
            return halfLengths.norm();
        case Type::HalfSpace:
            return SimTK::Infinity;
        case Type::Cylinder:
            return std::hypot(radius, 0.5 * length);
        case Type::Ellipsoid:
            return std::max({semiAxes[0], semiAxes[1], semiAxes[2]});
        case Type::ConvexMesh:
            return polytope ? polytope->getBoundingRadius() : SimTK::Infinity;
    }
    return SimTK::Infinity;
}

SimTK::Transform findGeometryPose(const model::Geometry& geometry) {
    return system::toSimTKTransform(geometry.X_BG, "geometry '" + geometry.name + "': X_BG");
}

}  // namespace graspsim::contact
