#include "graspsim/contact/surface_point.h"

#include "box_signed_distance.h"
#include "object_solid_surface.h"

#include <algorithm>

namespace graspsim::contact {

namespace {

// Nearest point on a sphere of radius r about C to Q, with fallback direction `away` at Q = C.
SurfacePoint findSphereSurface(const SimTK::Vec3& p_SC, double r, const SimTK::Vec3& p_SQ,
                               const SimTK::Vec3& away) {
    const SimTK::Vec3 r_CQ = p_SQ - p_SC;
    const double centreDistance = r_CQ.norm();
    SurfacePoint result;
    result.n_S = centreDistance > 0 ? SimTK::UnitVec3(r_CQ / centreDistance, true) : SimTK::UnitVec3(away);
    result.distance = centreDistance - r;
    result.p_SP = p_SC + r * SimTK::Vec3(result.n_S);
    return result;
}

SurfacePoint findBoxSurfacePoint(const SimTK::Vec3& h, const SimTK::Vec3& p_SQ) {
    const BoxSurfacePoint box = findBoxSurface(h, p_SQ);
    SurfacePoint result;
    result.distance = box.distance;
    if (box.distance > 0) {
        result.n_S = box.n_S;
        for (int i = 0; i < 3; ++i) result.p_SP[i] = std::clamp(p_SQ[i], -h[i], h[i]);
        return result;
    }
    const int axis = box.tiedAxes[0];
    const int sign = box.tiedSigns[0];
    result.p_SP = p_SQ;
    result.p_SP[axis] = sign * h[axis];
    SimTK::Vec3 n(0);
    n[axis] = sign;
    result.n_S = SimTK::UnitVec3(n, true);
    return result;
}

// Cylinder, ellipsoid, convex mesh. Where a point inside is equally deep below two faces the
// contact normal is their normalized sum; here the normal is that of the face P lies on, so
// that Q - P is along it.
SurfacePoint findObjectSurfacePoint(const ContactShape& shape, const SimTK::Vec3& p_SQ) {
    const ObjectSurface object = findObjectSurface(shape, p_SQ);
    SurfacePoint result;
    result.distance = object.distance;
    result.p_SP = object.p_SP;
    const SimTK::Vec3 r_PQ = p_SQ - object.p_SP;
    result.n_S = object.distance != 0 && r_PQ.norm() > 0
                     ? SimTK::UnitVec3(r_PQ / object.distance)
                     : object.n_S;
    return result;
}

}  // namespace

SurfacePoint findSurfacePoint(const ContactShape& shape, const SimTK::Vec3& p_SQ) {
    switch (shape.type) {
        case ContactShape::Type::Sphere:
            return findSphereSurface(SimTK::Vec3(0), shape.radius, p_SQ, SimTK::Vec3(0, 0, 1));
        case ContactShape::Type::Capsule: {
            const double z = std::clamp(p_SQ[2], -shape.length / 2, shape.length / 2);
            return findSphereSurface(SimTK::Vec3(0, 0, z), shape.radius, p_SQ, SimTK::Vec3(1, 0, 0));
        }
        case ContactShape::Type::Box:
            return findBoxSurfacePoint(shape.halfLengths, p_SQ);
        case ContactShape::Type::HalfSpace: {
            SurfacePoint result;
            result.distance = p_SQ[2];
            result.p_SP = SimTK::Vec3(p_SQ[0], p_SQ[1], 0);
            result.n_S = SimTK::UnitVec3(0, 0, 1);
            return result;
        }
        case ContactShape::Type::Cylinder:
        case ContactShape::Type::Ellipsoid:
        case ContactShape::Type::ConvexMesh:
            return findObjectSurfacePoint(shape, p_SQ);
    }
    return {};
}

}  // namespace graspsim::contact
