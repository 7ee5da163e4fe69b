#include "box_contact.h"

#include <array>
#include <cmath>
#include <utility>

#include "box_signed_distance.h"
#include "convex_line_search.h"
#include "swept_sphere_contact.h"

namespace graspsim::contact {

namespace {

// A box's 8 vertices in its frame, signs (sx, sy, sz) from the bits of the index.
SimTK::Vec3 findVertex(const SimTK::Vec3& h, int index) {
    return SimTK::Vec3((index & 1) ? h[0] : -h[0], (index & 2) ? h[1] : -h[1],
                       (index & 4) ? h[2] : -h[2]);
}

// A box's 12 edges: edge (axis, s1, s2) runs along `axis` at the signs s1, s2 of the other two
// axes (in increasing order). Its index is axis * 4 + (s1 > 0) * 2 + (s2 > 0).
struct BoxEdge {
    int axis = 0;
    int otherAxes[2] = {1, 2};
    int signs[2] = {1, 1};
    int getIndex() const { return axis * 4 + (signs[0] > 0) * 2 + (signs[1] > 0); }
};

BoxEdge makeEdge(int index) {
    BoxEdge edge;
    edge.axis = index / 4;
    edge.otherAxes[0] = edge.axis == 0 ? 1 : 0;
    edge.otherAxes[1] = edge.axis == 2 ? 1 : 2;
    edge.signs[0] = (index & 2) ? 1 : -1;
    edge.signs[1] = (index & 1) ? 1 : -1;
    return edge;
}

// The point of `edge` at the other axes' faces, with `along` on its own axis, in the box frame.
SimTK::Vec3 findEdgePoint(const SimTK::Vec3& h, const BoxEdge& edge, double along) {
    SimTK::Vec3 p;
    p[edge.axis] = along;
    p[edge.otherAxes[0]] = edge.signs[0] * h[edge.otherAxes[0]];
    p[edge.otherAxes[1]] = edge.signs[1] * h[edge.otherAxes[1]];
    return p;
}

// Whether the segment from e0 to e1 meets the box |x_i| <= h_i (slab clipping).
bool intersectsBox(const SimTK::Vec3& h, const SimTK::Vec3& e0, const SimTK::Vec3& e1) {
    double tIn = 0, tOut = 1;
    for (int i = 0; i < 3; ++i) {
        const double d = e1[i] - e0[i];
        if (d == 0) {
            if (std::abs(e0[i]) > h[i]) return false;
            continue;
        }
        double t0 = (-h[i] - e0[i]) / d, t1 = (h[i] - e0[i]) / d;
        if (t0 > t1) std::swap(t0, t1);
        tIn = std::max(tIn, t0);
        tOut = std::min(tOut, t1);
        if (tIn > tOut) return false;
    }
    return true;
}

// Which edge-edge crossings were already counted, [edge of the caller's A][edge of its B].
using EdgeCrossings = std::array<std::array<bool, 12>, 12>;

// One direction of the box-box test: box P (penetrating, pose X_QP in Q's frame) against box Q
// (penetrated, pose X_GQ). normalSign is -1 when P is the caller's A (normal from A to B
// points into Q, against Q's outward normal) and +1 when P is B.
struct PenetrationPass {
    const ContactShape& p;
    const ContactShape& q;
    SimTK::Transform X_QP;
    const SimTK::Transform& X_GQ;
    double normalSign;

    void appendVertexContacts(std::vector<ContactPoint>& contacts) const;
    // Appends edge contacts; edge-edge crossings are marked in `crossings` and skipped when
    // already marked.
    void appendEdgeContacts(EdgeCrossings& crossings, std::vector<ContactPoint>& contacts) const;

private:
    bool appendEdgeEdgeContact(const SimTK::Vec3& e0, const SimTK::Vec3& e1,
                               const BoxSurfacePoint& surface, const BoxEdge& edgeP,
                               EdgeCrossings& crossings, std::vector<ContactPoint>& contacts) const;
    void appendContact(const SimTK::Vec3& p_Q, const SimTK::Vec3& n_Q, double depth, double radius,
                       std::vector<ContactPoint>& contacts) const;
};

void PenetrationPass::appendContact(const SimTK::Vec3& p_Q, const SimTK::Vec3& n_Q, double depth,
                                    double radius, std::vector<ContactPoint>& contacts) const {
    ContactPoint contact;
    contact.p_G = X_GQ * p_Q;
    contact.n_G = SimTK::UnitVec3(normalSign * (X_GQ.R() * n_Q), true);
    contact.depth = depth;
    contact.radius = radius;
    contacts.push_back(contact);
}

void PenetrationPass::appendVertexContacts(std::vector<ContactPoint>& contacts) const {
    for (int i = 0; i < 8; ++i) {
        const SimTK::Vec3 v_Q = X_QP * findVertex(p.halfLengths, i);
        const BoxSurfacePoint surface = findBoxSurface(q.halfLengths, v_Q);
        if (surface.distance >= 0) continue;
        const double depth = -surface.distance;
        // Midway between the vertex and Q's surface point v + depth n.
        appendContact(v_Q + (0.5 * depth) * surface.n_S, surface.n_S, depth, p.cornerRadius,
                      contacts);
    }
}

void PenetrationPass::appendEdgeContacts(EdgeCrossings& crossings,
                                         std::vector<ContactPoint>& contacts) const {
    for (int index = 0; index < 12; ++index) {
        const BoxEdge edge = makeEdge(index);
        const double h = p.halfLengths[edge.axis];
        const SimTK::Vec3 e0 = X_QP * findEdgePoint(p.halfLengths, edge, -h);
        const SimTK::Vec3 e1 = X_QP * findEdgePoint(p.halfLengths, edge, h);
        if (!intersectsBox(q.halfLengths, e0, e1)) continue;
        const SimTK::Vec3 d = e1 - e0;
        const auto distance = [&](double t) {
            return calcBoxSignedDistance(q.halfLengths, e0 + t * d);
        };
        const ArgminInterval deepest = findConvexArgminInterval(distance, kFlatTolerance);
        // A deepest point at an end of the edge is a vertex, counted by appendVertexContacts.
        if (deepest.lower <= 0 || deepest.upper >= 1) continue;
        const SimTK::Vec3 point = e0 + deepest.middle() * d;
        const BoxSurfacePoint surface = findBoxSurface(q.halfLengths, point);
        if (surface.distance >= 0) continue;
        if (surface.tiedAxisCount == 2 &&
            appendEdgeEdgeContact(e0, e1, surface, edge, crossings, contacts)) {
            continue;
        }
        const double depth = -surface.distance;
        appendContact(point + (0.5 * depth) * surface.n_S, surface.n_S, depth, p.cornerRadius,
                      contacts);
    }
}

// An edge of P whose deepest point inside Q is equally deep below two adjacent faces of Q
// crosses the edge of Q where those faces meet. The SDF depth there underestimates the overlap
// (by up to a factor sqrt 2), so use the exact line-line geometry: normal along the cross
// product of the edges, depth = gap between the two lines along it. Returns false (caller
// falls back to the SDF contact) when the edges are parallel or the lines do not overlap.
bool PenetrationPass::appendEdgeEdgeContact(const SimTK::Vec3& e0, const SimTK::Vec3& e1,
                                            const BoxSurfacePoint& surface, const BoxEdge& edgeP,
                                            EdgeCrossings& crossings,
                                            std::vector<ContactPoint>& contacts) const {
    BoxEdge edgeQ;
    edgeQ.axis = 3 - surface.tiedAxes[0] - surface.tiedAxes[1];
    edgeQ.otherAxes[0] = surface.tiedAxes[0];  // tied axes come in increasing order
    edgeQ.otherAxes[1] = surface.tiedAxes[1];
    edgeQ.signs[0] = surface.tiedSigns[0];
    edgeQ.signs[1] = surface.tiedSigns[1];
    const SimTK::Vec3 u = e1 - e0;
    SimTK::Vec3 v(0);  // along Q's edge
    v[edgeQ.axis] = 1;
    SimTK::Vec3 o = SimTK::cross(u, v);
    const double sine = o.norm() / u.norm();
    if (sine <= 1e-9) return false;
    o /= o.norm();
    if (SimTK::dot(o, surface.n_S) < 0) o = -o;  // outward from Q, like Q's faces at its edge
    // Closest points of the lines e0 + s u and b0 + t v (|v| = 1).
    const SimTK::Vec3 b0 = findEdgePoint(q.halfLengths, edgeQ, 0);
    const SimTK::Vec3 w = e0 - b0;
    const double uu = SimTK::dot(u, u), uv = SimTK::dot(u, v), uw = SimTK::dot(u, w),
                 vw = SimTK::dot(v, w);
    const double denominator = uu - uv * uv;
    const SimTK::Vec3 onP = e0 + ((uv * vw - uw) / denominator) * u;
    const SimTK::Vec3 onQ = b0 + ((uu * vw - uv * uw) / denominator) * v;
    const double depth = SimTK::dot(onQ - onP, o);
    if (depth <= 0) return false;
    const int indexP = edgeP.getIndex(), indexQ = edgeQ.getIndex();
    bool& seen = normalSign < 0 ? crossings[indexP][indexQ] : crossings[indexQ][indexP];
    if (!seen) {
        seen = true;
        const double radius = p.cornerRadius * q.cornerRadius / (p.cornerRadius + q.cornerRadius);
        appendContact(0.5 * (onP + onQ), o, depth, radius, contacts);
    }
    return true;
}

}  // namespace

void appendBoxHalfSpaceContacts(const ContactShape& box, const SimTK::Transform& X_GB,
                                const SimTK::Transform& X_GH, std::vector<ContactPoint>& contacts) {
    const SimTK::Transform X_HB = ~X_GH * X_GB;
    if (X_HB.p()[2] >= box.calcBoundingRadius()) return;
    const SimTK::UnitVec3 up_G = X_GH.R().z();  // the half-space's outward normal
    for (int i = 0; i < 8; ++i) {
        const SimTK::Vec3 v_H = X_HB * findVertex(box.halfLengths, i);
        if (v_H[2] >= 0) continue;
        ContactPoint contact;
        contact.depth = -v_H[2];
        contact.p_G = X_GH * (v_H + SimTK::Vec3(0, 0, 0.5 * contact.depth));
        contact.n_G = -up_G;
        contact.radius = box.cornerRadius;
        contacts.push_back(contact);
    }
}

namespace {

// Whether a face normal of Q (box q, with p posed at X_QP) separates the two boxes: along it the
// centres lie farther apart than q's half-length plus p's half-extent. Separated boxes do not
// overlap, so they have no contact; a cheap early exit before the vertex and edge passes.
bool isSeparatedByFaceOf(const ContactShape& q, const ContactShape& p, const SimTK::Transform& X_QP) {
    const SimTK::Mat33& R = X_QP.R().asMat33();
    for (int i = 0; i < 3; ++i) {
        const double extent = std::abs(R(i, 0)) * p.halfLengths[0] + std::abs(R(i, 1)) * p.halfLengths[1] +
                              std::abs(R(i, 2)) * p.halfLengths[2];
        if (std::abs(X_QP.p()[i]) >= q.halfLengths[i] + extent) return true;
    }
    return false;
}

}  // namespace

void appendBoxBoxContacts(const ContactShape& a, const SimTK::Transform& X_GA,
                          const ContactShape& b, const SimTK::Transform& X_GB,
                          std::vector<ContactPoint>& contacts) {
    if ((X_GB.p() - X_GA.p()).norm() >= a.calcBoundingRadius() + b.calcBoundingRadius()) return;
    const SimTK::Transform X_BA = ~X_GB * X_GA;
    if (isSeparatedByFaceOf(b, a, X_BA) || isSeparatedByFaceOf(a, b, ~X_BA)) return;
    const PenetrationPass aIntoB{a, b, X_BA, X_GB, -1};
    const PenetrationPass bIntoA{b, a, ~X_BA, X_GA, +1};
    aIntoB.appendVertexContacts(contacts);
    bIntoA.appendVertexContacts(contacts);
    EdgeCrossings crossings{};
    aIntoB.appendEdgeContacts(crossings, contacts);
    bIntoA.appendEdgeContacts(crossings, contacts);
}

}  // namespace graspsim::contact
