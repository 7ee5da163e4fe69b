#include "swept_sphere_contact.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "box_signed_distance.h"
#include "convex_line_search.h"

namespace graspsim::contact {

namespace {

SimTK::Vec3 findClosestPointOnSegment(const SimTK::Vec3& p, const SimTK::Vec3& s0,
                                      const SimTK::Vec3& s1) {
    const SimTK::Vec3 d = s1 - s0;
    const double dd = SimTK::dot(d, d);
    if (dd == 0) return s0;
    return s0 + std::clamp(SimTK::dot(p - s0, d) / dd, 0.0, 1.0) * d;
}

SimTK::Vec3 findCentre(const SweptSphere& s) { return 0.5 * (s.p0_G + s.p1_G); }

double calcBoundingRadius(const SweptSphere& s) {
    return s.radius + 0.5 * (s.p1_G - s.p0_G).norm();
}

// Parameter s in [0, 1] on segment a of its point closest to b when the two are parallel: the
// middle of their overlap along the common direction, or a's end nearer b without overlap.
// Mid-overlap is the same place whichever segment comes first.
double findParallelClosestParameter(const SweptSphere& a, const SweptSphere& b) {
    const SimTK::Vec3 dA = a.p1_G - a.p0_G;
    const double aa = SimTK::dot(dA, dA);
    double s0 = SimTK::dot(b.p0_G - a.p0_G, dA) / aa, s1 = SimTK::dot(b.p1_G - a.p0_G, dA) / aa;
    if (s0 > s1) std::swap(s0, s1);
    const double lower = std::max(0.0, s0), upper = std::min(1.0, s1);
    if (lower <= upper) return 0.5 * (lower + upper);
    return s1 < 0 ? 0.0 : 1.0;
}

// The closest points of the cores of a and b (segments, possibly of zero length): the classic
// clamped solution of the 2x2 normal equations, with parallel segments (sin^2 of the angle
// below 1e-12) handled apart so that the contact sits mid-overlap instead of at an arbitrary
// point of the overlap.
std::pair<SimTK::Vec3, SimTK::Vec3> findClosestCorePoints(const SweptSphere& a,
                                                          const SweptSphere& b) {
    const SimTK::Vec3 dA = a.p1_G - a.p0_G, dB = b.p1_G - b.p0_G, r = a.p0_G - b.p0_G;
    const double aa = SimTK::dot(dA, dA), bb = SimTK::dot(dB, dB);
    if (aa == 0) return {a.p0_G, findClosestPointOnSegment(a.p0_G, b.p0_G, b.p1_G)};
    if (bb == 0) return {findClosestPointOnSegment(b.p0_G, a.p0_G, a.p1_G), b.p0_G};
    const double ab = SimTK::dot(dA, dB), ar = SimTK::dot(dA, r), br = SimTK::dot(dB, r);
    const double denominator = aa * bb - ab * ab;
    double s = 0;
    if (denominator > 1e-12 * aa * bb) {
        s = std::clamp((ab * br - ar * bb) / denominator, 0.0, 1.0);
    } else {
        s = findParallelClosestParameter(a, b);
    }
    const SimTK::Vec3 onA = a.p0_G + s * dA;
    const SimTK::Vec3 onB = findClosestPointOnSegment(onA, b.p0_G, b.p1_G);
    return {findClosestPointOnSegment(onB, a.p0_G, a.p1_G), onB};
}

}  // namespace

SweptSphere makeSweptSphere(const ContactShape& shape, const SimTK::Transform& X_GS) {
    SweptSphere swept;
    swept.radius = shape.radius;
    if (shape.type == ContactShape::Type::Capsule && shape.length > 0) {
        const SimTK::Vec3 halfAxis_G = X_GS.R().z() * (0.5 * shape.length);
        swept.p0_G = X_GS.p() - halfAxis_G;
        swept.p1_G = X_GS.p() + halfAxis_G;
    } else {
        swept.p0_G = swept.p1_G = X_GS.p();
    }
    return swept;
}

void appendSweptSweptContact(const SweptSphere& a, const SweptSphere& b,
                             std::vector<ContactPoint>& contacts) {
    const double reach = a.radius + b.radius;
    if ((findCentre(b) - findCentre(a)).norm() >= calcBoundingRadius(a) + calcBoundingRadius(b)) {
        return;
    }
    const auto [cA, cB] = findClosestCorePoints(a, b);
    const SimTK::Vec3 d = cB - cA;
    const double distance = d.norm();
    if (distance >= reach) return;
    ContactPoint contact;
    // Coincident cores leave the direction undefined; any unit vector is as good as another.
    contact.n_G = distance > 0 ? SimTK::UnitVec3(d / distance, true) : SimTK::UnitVec3(1, 0, 0);
    contact.depth = reach - distance;
    // Midway between a's surface point cA + rA n and b's surface point cB - rB n.
    contact.p_G = 0.5 * (cA + cB) + (0.5 * (a.radius - b.radius)) * contact.n_G;
    contact.radius = a.radius * b.radius / reach;
    contacts.push_back(contact);
}

namespace {

// The point of the core with the least signed distance to the solid, in the solid's frame S.
SimTK::Vec3 findDeepestCorePoint(const SimTK::Vec3& c0_S, const SimTK::Vec3& c1_S,
                                 const ContactShape& solid) {
    if (c0_S == c1_S) return c0_S;
    const SimTK::Vec3 d = c1_S - c0_S;
    if (solid.type == ContactShape::Type::HalfSpace) {
        // The half-space's distance z is linear along the segment: lowest end, or the middle
        // when the segment lies parallel to the surface.
        if (std::abs(d[2]) <= kFlatTolerance) return 0.5 * (c0_S + c1_S);
        return d[2] > 0 ? c0_S : c1_S;
    }
    const auto distance = [&](double t) {
        return calcBoxSignedDistance(solid.halfLengths, c0_S + t * d);
    };
    return c0_S + findConvexArgminInterval(distance, kFlatTolerance).middle() * d;
}

// Whether the box's signed distance stays above `reach` all along the segment, judged from
// its ends alone: the distance changes by at most 1 m per m along the segment, so its minimum
// is at least (f(0) + f(1) - length) / 2. Spares the line search for most near misses.
bool isSurelyOutOfReach(const SimTK::Vec3& c0_S, const SimTK::Vec3& c1_S, const ContactShape& box,
                        double reach) {
    const double f0 = calcBoxSignedDistance(box.halfLengths, c0_S);
    const double f1 = calcBoxSignedDistance(box.halfLengths, c1_S);
    return 0.5 * (f0 + f1 - (c1_S - c0_S).norm()) >= reach;
}

// Signed distance and outward normal of the solid at p_S.
BoxSurfacePoint findSolidSurface(const ContactShape& solid, const SimTK::Vec3& p_S) {
    if (solid.type == ContactShape::Type::Box) return findBoxSurface(solid.halfLengths, p_S);
    BoxSurfacePoint surface;
    surface.distance = p_S[2];
    surface.n_S = SimTK::UnitVec3(0, 0, 1);
    return surface;
}

}  // namespace

void appendCoreContact(const CoreSurface& surface, double radius, double depthOffset, const SimTK::Transform& X_GS,
                       std::vector<ContactPoint>& contacts) {
    const double depth = radius - surface.distance - depthOffset;
    if (!(depth > 0)) return;
    ContactPoint contact;
    contact.depth = depth;
    // Solid surface point: core - distance n; swept surface point: core - radius n.
    contact.p_G = X_GS * (surface.core_S - (0.5 * (surface.distance + radius)) * surface.n_S);
    contact.n_G = -(X_GS.R() * surface.n_S);
    contact.radius = surface.radius;
    contacts.push_back(contact);
}

void appendCoreEndContacts(const CoreSurface& end0, const CoreSurface& end1, const CoreSurface& deepest, double radius,
                           const SimTK::Transform& X_GS, std::vector<ContactPoint>& contacts) {
    appendCoreContact(end0, radius, 0, X_GS, contacts);
    appendCoreContact(end1, radius, 0, X_GS, contacts);
    // The interior minimum fades out as it reaches an end: its depth less the deeper end's is 0 there.
    // Where the core lies parallel to a face its minimum is an end's to rounding; no contact of
    // kFlatTolerance joins the two ends'.
    const double endDepth = std::max(0.0, radius - std::min(end0.distance, end1.distance));
    if (endDepth > 0 && !(radius - deepest.distance - endDepth > kFlatTolerance)) return;
    appendCoreContact(deepest, radius, endDepth, X_GS, contacts);
}

void appendSweptSolidContact(const SweptSphere& swept, const ContactShape& solid, const SimTK::Transform& X_GS,
                             CapsuleContact rule, std::vector<ContactPoint>& contacts) {
    const SimTK::Vec3 centre_S = ~X_GS * findCentre(swept);
    const double sweptBound = calcBoundingRadius(swept);
    if (solid.type == ContactShape::Type::Box
            ? centre_S.norm() >= sweptBound + solid.calcBoundingRadius()
            : centre_S[2] >= sweptBound) {
        return;
    }
    const SimTK::Vec3 c0_S = ~X_GS * swept.p0_G, c1_S = ~X_GS * swept.p1_G;
    if (solid.type == ContactShape::Type::Box &&
        isSurelyOutOfReach(c0_S, c1_S, solid, swept.radius)) {
        return;
    }
    const auto surfaceAt = [&](const SimTK::Vec3& core_S) {
        const BoxSurfacePoint surface = findSolidSurface(solid, core_S);
        return CoreSurface{core_S, surface.distance, surface.n_S, swept.radius};
    };
    appendCoreContacts(c0_S, c1_S, findDeepestCorePoint(c0_S, c1_S, solid), swept.radius, rule, X_GS, surfaceAt, contacts);
}

}  // namespace graspsim::contact
