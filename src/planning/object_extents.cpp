#include "object_extents.h"

#include "graspsim/contact/surface_point.h"
#include "graspsim/error.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace graspsim::planning {

ObjectExtents findObjectExtents(const contact::ContactShape& shape) {
    ObjectExtents extents;
    if (shape.type == contact::ContactShape::Type::Box) extents.halfExtents = shape.halfLengths;
    if (shape.type == contact::ContactShape::Type::Ellipsoid) extents.halfExtents = shape.semiAxes;
    if (shape.type != contact::ContactShape::Type::ConvexMesh) return extents;
    const double far = 100;  // m, as calcObjectWidth: the support error is below 1e-4 m
    for (int k = 0; k < 3; ++k) {
        const SimTK::Vec3 u = SimTK::Vec3(k == 0, k == 1, k == 2);
        const double plus = contact::findSurfacePoint(shape, far * u).distance;    // far less the support along +u
        const double minus = contact::findSurfacePoint(shape, -far * u).distance;  // and along -u
        extents.halfExtents[k] = far - (plus + minus) / 2;
        extents.centre_S[k] = (minus - plus) / 2;
    }
    return extents;
}

double calcObjectWidth(const contact::ContactShape& shape) {
    const double far = 100;  // m: the support error is (extent^2)/(2 far), below 1e-4 m
    double width = SimTK::Infinity;
    const int n = 400;  // Fibonacci sphere (half of it: each direction is paired with its opposite)
    for (int i = 0; i < n; ++i) {
        const double z = 1 - (i + 0.5) / n, r = std::sqrt(1 - z * z), phi = i * 2.399963229728653;
        const SimTK::Vec3 u(r * std::cos(phi), r * std::sin(phi), z);
        const double d1 = contact::findSurfacePoint(shape, far * u).distance;
        const double d2 = contact::findSurfacePoint(shape, -far * u).distance;
        width = std::min(width, 2 * far - d1 - d2);
    }
    for (int k = 0; k < 3; ++k) {
        const SimTK::Vec3 u = SimTK::Vec3(k == 0, k == 1, k == 2);
        width = std::min(width, 2 * far - contact::findSurfacePoint(shape, far * u).distance -
                                    contact::findSurfacePoint(shape, -far * u).distance);
    }
    return width;
}

bool hasEdges(const contact::ContactShape& shape) {
    return shape.type == contact::ContactShape::Type::Box || shape.type == contact::ContactShape::Type::ConvexMesh;
}

SmoothStandIn findSmoothStandIn(const contact::ContactShape& shape) {
    const ObjectExtents extents = findObjectExtents(shape);
    if (!(extents.halfExtents[0] > 0 && extents.halfExtents[1] > 0 && extents.halfExtents[2] > 0)) {
        std::ostringstream out;
        out << "grasp plan: no smooth stand-in for an object of half-extents " << extents.halfExtents
            << " m (a box or a convex mesh has three positive ones)";
        throw Error(out.str());
    }
    return {contact::ContactShape::ellipsoid(extents.halfExtents), SimTK::Transform(extents.centre_S)};
}

}  // namespace graspsim::planning
