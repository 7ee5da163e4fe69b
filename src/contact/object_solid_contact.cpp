#include "object_solid_contact.h"

#include <cmath>

#include "convex_line_search.h"
#include "ellipsoid_distance.h"
#include "object_solid_surface.h"

namespace graspsim::contact {

double combineRadii(double a, double b) {
    if (std::isinf(a)) return b;
    if (std::isinf(b)) return a;
    return a * b / (a + b);
}

namespace {

// The point of the core (c0..c1, in S) with the least signed distance to the solid: the
// bracketing search of swept_sphere_contact.cpp on the solid's convex SDF, with the middle of a
// flat stretch.
SimTK::Vec3 findDeepestObjectCorePoint(const SimTK::Vec3& c0_S, const SimTK::Vec3& c1_S,
                                       const ContactShape& solid) {
    if (c0_S == c1_S) return c0_S;
    const SimTK::Vec3 d = c1_S - c0_S;
    const auto distance = [&](double t) { return calcObjectSignedDistance(solid, c0_S + t * d); };
    return c0_S + findConvexArgminInterval(distance, kFlatTolerance).middle() * d;
}

}  // namespace

void appendSweptObjectContact(const SweptSphere& swept, const ContactShape& solid, const SimTK::Transform& X_GS,
                              CapsuleContact rule, std::vector<ContactPoint>& contacts) {
    const SimTK::Vec3 c0_S = ~X_GS * swept.p0_G, c1_S = ~X_GS * swept.p1_G;
    const double sweptBound = swept.radius + 0.5 * (c1_S - c0_S).norm();
    if ((0.5 * (c0_S + c1_S)).norm() >= sweptBound + solid.calcBoundingRadius()) return;
    if (c0_S != c1_S) {
        // The SDF changes by at most 1 m per m, so its minimum along the core is at least
        // (f(0) + f(1) - length) / 2: most near misses need no line search.
        const double f0 = calcObjectSignedDistance(solid, c0_S);
        const double f1 = calcObjectSignedDistance(solid, c1_S);
        if (0.5 * (f0 + f1 - (c1_S - c0_S).norm()) >= swept.radius) return;
    }
    const auto surfaceAt = [&](const SimTK::Vec3& core_S) {
        const ObjectSurface surface = findObjectSurface(solid, core_S);
        return CoreSurface{core_S, surface.distance, surface.n_S, combineRadii(swept.radius, surface.curvatureRadius)};
    };
    appendCoreContacts(c0_S, c1_S, findDeepestObjectCorePoint(c0_S, c1_S, solid), swept.radius, rule, X_GS, surfaceAt,
                       contacts);
}

namespace {

// The solid's deepest point below the plane z_H = 0 with unit "down" direction u_S (-z_H in
// S), and the Hertz radius there. Cylinder: on the side line facing down, its middle when the
// side lies flat (else its lower end), or the middle of the cap facing down when the axis is
// vertical; both with the cylinder's radius. Ellipsoid: its support point.
struct SupportPoint {
    SimTK::Vec3 p_S{0, 0, 0};
    double radius = 0;
};

SupportPoint findCylinderSupport(const ContactShape& c, const SimTK::Vec3& u_S) {
    const double radial = std::hypot(u_S[0], u_S[1]), half = 0.5 * c.length;
    SupportPoint support;
    support.radius = c.radius;
    if (radial <= 1e-12) {
        support.p_S = SimTK::Vec3(0, 0, u_S[2] > 0 ? half : -half);
        return support;
    }
    const SimTK::Vec3 side(c.radius * u_S[0] / radial, c.radius * u_S[1] / radial, 0);
    // Height of the side line's ends along u: linear in z, flat when u is normal to the axis.
    const double rise = u_S[2] * c.length;
    if (std::abs(rise) <= kFlatTolerance) {
        support.p_S = side;
    } else {
        support.p_S = side + SimTK::Vec3(0, 0, u_S[2] > 0 ? half : -half);
    }
    return support;
}

}  // namespace

void appendObjectHalfSpaceContacts(const ContactShape& solid, const SimTK::Transform& X_GS,
                                   const SimTK::Transform& X_GH,
                                   std::vector<ContactPoint>& contacts) {
    const SimTK::Transform X_HS = ~X_GH * X_GS;
    if (X_HS.p()[2] >= solid.calcBoundingRadius()) return;
    const SimTK::UnitVec3 up_G = X_GH.R().z();
    const auto append = [&](const SimTK::Vec3& p_S, double radius) {
        const SimTK::Vec3 p_H = X_HS * p_S;
        if (p_H[2] >= 0) return;
        ContactPoint contact;
        contact.depth = -p_H[2];
        contact.p_G = X_GH * (p_H + SimTK::Vec3(0, 0, 0.5 * contact.depth));
        contact.n_G = -up_G;
        contact.radius = radius;
        contacts.push_back(contact);
    };
    const SimTK::Vec3 down_S = ~X_HS.R() * SimTK::Vec3(0, 0, -1);
    switch (solid.type) {
        case ContactShape::Type::ConvexMesh:
            for (const SimTK::Vec3& v : solid.polytope->getVertices()) append(v, solid.cornerRadius);
            break;
        case ContactShape::Type::Cylinder: {
            const SupportPoint s = findCylinderSupport(solid, down_S);
            append(s.p_S, s.radius);
            break;
        }
        default: {
            const SimTK::Vec3 p = findEllipsoidSupportPoint(solid.semiAxes, down_S);
            append(p, calcEllipsoidCurvatureRadius(solid.semiAxes, p));
            break;
        }
    }
}

}  // namespace graspsim::contact
