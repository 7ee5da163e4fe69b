#include "object_solid_surface.h"

#include <algorithm>
#include <cmath>

#include "ellipsoid_distance.h"

namespace graspsim::contact {

namespace {

// Radial unit vector of p_S about the z axis (+x on the axis), and the radial distance.
SimTK::Vec3 findRadialDirection(const SimTK::Vec3& p_S, double& rho) {
    rho = std::hypot(p_S[0], p_S[1]);
    return rho > 0 ? SimTK::Vec3(p_S[0] / rho, p_S[1] / rho, 0) : SimTK::Vec3(1, 0, 0);
}

double calcCylinderSignedDistance(const ContactShape& c, const SimTK::Vec3& p_S) {
    const double radial = std::hypot(p_S[0], p_S[1]) - c.radius;
    const double axial = std::abs(p_S[2]) - 0.5 * c.length;
    if (radial > 0 || axial > 0) return std::hypot(std::max(radial, 0.0), std::max(axial, 0.0));
    return std::max(radial, axial);
}

ObjectSurface findCylinderSurface(const ContactShape& c, const SimTK::Vec3& p_S) {
    double rho = 0;
    const SimTK::Vec3 u = findRadialDirection(p_S, rho);
    const double halfLength = 0.5 * c.length, sign = p_S[2] < 0 ? -1 : 1;
    const double radial = rho - c.radius, axial = std::abs(p_S[2]) - halfLength;
    const SimTK::Vec3 onSide = c.radius * u + SimTK::Vec3(0, 0, p_S[2]);
    const SimTK::Vec3 onCap(p_S[0], p_S[1], sign * halfLength);
    ObjectSurface s;
    if (radial > 0 && axial > 0) {  // nearest to a rim
        s.p_SP = c.radius * u + SimTK::Vec3(0, 0, sign * halfLength);
        s.distance = (p_S - s.p_SP).norm();
        s.n_S = SimTK::UnitVec3((p_S - s.p_SP) / s.distance, true);
        return s;
    }
    const bool tied = radial <= 0 && axial <= 0 && std::abs(radial - axial) <= kCylinderTieTolerance;
    if (tied) {
        s.distance = std::max(radial, axial);
        s.p_SP = radial >= axial ? onSide : onCap;
        s.n_S = SimTK::UnitVec3(u + SimTK::Vec3(0, 0, sign));
    } else if (radial > axial) {
        s.distance = radial;
        s.p_SP = onSide;
        s.n_S = SimTK::UnitVec3(u, true);
        s.curvatureRadius = c.radius;
    } else {
        s.distance = axial;
        s.p_SP = onCap;
        s.n_S = SimTK::UnitVec3(0, 0, sign);
    }
    return s;
}

ObjectSurface findEllipsoidSurface(const ContactShape& e, const SimTK::Vec3& p_S) {
    const EllipsoidSurfacePoint point = findEllipsoidSurfacePoint(e.semiAxes, p_S);
    ObjectSurface s;
    s.distance = point.distance;
    s.p_SP = point.p_SP;
    s.n_S = calcEllipsoidNormal(e.semiAxes, point.p_SP);
    s.curvatureRadius = calcEllipsoidCurvatureRadius(e.semiAxes, point.p_SP);
    return s;
}

ObjectSurface findMeshSurface(const ContactShape& m, const SimTK::Vec3& p_S) {
    const ConvexPolytope::Surface surface = m.polytope->findSurface(p_S);
    ObjectSurface s;
    s.distance = surface.distance;
    s.p_SP = surface.p_SP;
    s.n_S = surface.n_S;
    s.tiedFaceCount = static_cast<int>(surface.tiedFaces.size());
    for (int k = 0; k < std::min(2, s.tiedFaceCount); ++k) s.tiedFaces[k] = surface.tiedFaces[k];
    return s;
}

}  // namespace

bool isObjectSolid(const ContactShape& shape) {
    return shape.type == ContactShape::Type::Cylinder ||
           shape.type == ContactShape::Type::Ellipsoid ||
           shape.type == ContactShape::Type::ConvexMesh;
}

double calcObjectSignedDistance(const ContactShape& solid, const SimTK::Vec3& p_S) {
    switch (solid.type) {
        case ContactShape::Type::Cylinder:
            return calcCylinderSignedDistance(solid, p_S);
        case ContactShape::Type::Ellipsoid:
            return findEllipsoidSurfacePoint(solid.semiAxes, p_S).distance;
        case ContactShape::Type::ConvexMesh:
            return solid.polytope->calcSignedDistance(p_S);
        default:
            return SimTK::NaN;
    }
}

ObjectSurface findObjectSurface(const ContactShape& solid, const SimTK::Vec3& p_S) {
    switch (solid.type) {
        case ContactShape::Type::Cylinder:
            return findCylinderSurface(solid, p_S);
        case ContactShape::Type::Ellipsoid:
            return findEllipsoidSurface(solid, p_S);
        default:
            return findMeshSurface(solid, p_S);
    }
}

}  // namespace graspsim::contact
