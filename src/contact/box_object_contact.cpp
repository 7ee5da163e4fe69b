#include "box_object_contact.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "box_signed_distance.h"
#include "convex_line_search.h"
#include "ellipsoid_distance.h"
#include "object_solid_contact.h"
#include "object_solid_surface.h"
#include "swept_sphere_contact.h"

namespace graspsim::contact {

namespace {

// A line along an edge of the penetrated solid, and the edge's index there.
struct EdgeLine {
    SimTK::Vec3 point{0, 0, 0};
    SimTK::Vec3 direction{0, 0, 1};  // unit
    int index = -1;
};

// What a feature pass needs of the penetrated solid at a point (in its frame).
struct PenetratedSurface {
    double distance = 0;
    SimTK::UnitVec3 n;
    double curvatureRadius = SimTK::Infinity;
    bool atEdge = false;  // inside, equally deep below exactly two faces meeting at `edge`
    EdgeLine edge;
};

// Whether the segment e0..e1 meets the convex region {x : dot(n_k, x) <= offset_k for all k}
// (Cyrus-Beck clipping). Planes are given by a callback plane(k, n, offset).
template <class Plane>
bool clipsPlanes(int count, const Plane& plane, const SimTK::Vec3& e0, const SimTK::Vec3& e1) {
    double tIn = 0, tOut = 1;
    const SimTK::Vec3 d = e1 - e0;
    for (int k = 0; k < count; ++k) {
        SimTK::Vec3 n;
        double offset = 0;
        plane(k, n, offset);
        const double gap = offset - SimTK::dot(n, e0), rate = SimTK::dot(n, d);
        if (rate == 0) {
            if (gap < 0) return false;
            continue;
        }
        const double t = gap / rate;
        (rate < 0 ? tIn : tOut) = rate < 0 ? std::max(tIn, t) : std::min(tOut, t);
        if (tIn > tOut) return false;
    }
    return true;
}

// Whether the segment meets the ellipsoid: in coordinates scaled by 1/e it meets the unit ball.
bool meetsEllipsoid(const SimTK::Vec3& e, const SimTK::Vec3& e0, const SimTK::Vec3& e1) {
    const SimTK::Vec3 p(e0[0] / e[0], e0[1] / e[1], e0[2] / e[2]);
    const SimTK::Vec3 d((e1[0] - e0[0]) / e[0], (e1[1] - e0[1]) / e[1], (e1[2] - e0[2]) / e[2]);
    const double a = SimTK::dot(d, d), b = SimTK::dot(p, d), c = SimTK::dot(p, p) - 1;
    if (c <= 0) return true;  // e0 inside
    const double discriminant = b * b - a * c;
    if (discriminant < 0 || a == 0) return false;
    const double tEnter = (-b - std::sqrt(discriminant)) / a;  // the first crossing
    return tEnter <= 1 && tEnter + 2 * std::sqrt(discriminant) / a >= 0;
}

// The box as the penetrated solid.
struct PenetratedBox {
    const ContactShape& shape;
    bool meetsSegment(const SimTK::Vec3& e0, const SimTK::Vec3& e1) const {
        const SimTK::Vec3& h = shape.halfLengths;
        return clipsPlanes(
            6,
            [&](int k, SimTK::Vec3& n, double& offset) {
                n = SimTK::Vec3(0);
                n[k / 2] = k % 2 ? 1 : -1;
                offset = h[k / 2];
            },
            e0, e1);
    }
    double calcDistance(const SimTK::Vec3& p) const { return calcBoxSignedDistance(shape.halfLengths, p); }
    PenetratedSurface findSurface(const SimTK::Vec3& p) const {
        const BoxSurfacePoint b = findBoxSurface(shape.halfLengths, p);
        PenetratedSurface s;
        s.distance = b.distance;
        s.n = b.n_S;
        if (b.distance < 0 && b.tiedAxisCount == 2) {
            const int axis = 3 - b.tiedAxes[0] - b.tiedAxes[1];
            s.atEdge = true;
            s.edge.point[b.tiedAxes[0]] = b.tiedSigns[0] * shape.halfLengths[b.tiedAxes[0]];
            s.edge.point[b.tiedAxes[1]] = b.tiedSigns[1] * shape.halfLengths[b.tiedAxes[1]];
            s.edge.point[axis] = 0;
            s.edge.direction = SimTK::Vec3(0);
            s.edge.direction[axis] = 1;
            s.edge.index = axis * 4 + (b.tiedSigns[0] > 0) * 2 + (b.tiedSigns[1] > 0);
        }
        return s;
    }
};

// A cylinder, ellipsoid or convex mesh as the penetrated solid.
struct PenetratedObject {
    const ContactShape& shape;
    // A cheap exact test that spares the line search for edges that do not enter the solid
    // (the cylinder's SDF is cheap enough without).
    bool meetsSegment(const SimTK::Vec3& e0, const SimTK::Vec3& e1) const {
        if (shape.type == ContactShape::Type::Ellipsoid) return meetsEllipsoid(shape.semiAxes, e0, e1);
        if (shape.type != ContactShape::Type::ConvexMesh) return true;
        const std::vector<ConvexPolytope::Face>& faces = shape.polytope->getFaces();
        return clipsPlanes(
            static_cast<int>(faces.size()),
            [&](int k, SimTK::Vec3& n, double& offset) {
                n = faces[k].normal.asVec3();
                offset = faces[k].offset;
            },
            e0, e1);
    }
    double calcDistance(const SimTK::Vec3& p) const { return calcObjectSignedDistance(shape, p); }
    PenetratedSurface findSurface(const SimTK::Vec3& p) const {
        const ObjectSurface o = findObjectSurface(shape, p);
        PenetratedSurface s;
        s.distance = o.distance;
        s.n = o.n_S;
        s.curvatureRadius = o.curvatureRadius;
        if (shape.type == ContactShape::Type::ConvexMesh && o.distance < 0 && o.tiedFaceCount == 2) {
            const int e = shape.polytope->findEdge(o.tiedFaces[0], o.tiedFaces[1]);
            if (e >= 0) {
                const ConvexPolytope::Edge& edge = shape.polytope->getEdges()[e];
                const SimTK::Vec3& v0 = shape.polytope->getVertices()[edge.vertex0];
                const SimTK::Vec3& v1 = shape.polytope->getVertices()[edge.vertex1];
                s.atEdge = true;
                s.edge = {v0, (v1 - v0) / (v1 - v0).norm(), e};
            }
        }
        return s;
    }
};

// The vertices and edges of the penetrating polytope (box or convex mesh), in its frame.
struct Features {
    std::vector<SimTK::Vec3> vertices;
    std::vector<std::pair<SimTK::Vec3, SimTK::Vec3>> edges;  // index = position
    double cornerRadius = 0;
};

Features makeBoxFeatures(const ContactShape& box) {
    Features f;
    const SimTK::Vec3& h = box.halfLengths;
    for (int i = 0; i < 8; ++i) {
        f.vertices.emplace_back((i & 1) ? h[0] : -h[0], (i & 2) ? h[1] : -h[1], (i & 4) ? h[2] : -h[2]);
    }
    // Edge index axis * 4 + (s1 > 0) * 2 + (s2 > 0), as PenetratedBox numbers them.
    for (int index = 0; index < 12; ++index) {
        const int axis = index / 4;
        const int o0 = axis == 0 ? 1 : 0, o1 = axis == 2 ? 1 : 2;
        SimTK::Vec3 p;
        p[o0] = (index & 2) ? h[o0] : -h[o0];
        p[o1] = (index & 1) ? h[o1] : -h[o1];
        SimTK::Vec3 q = p;
        p[axis] = -h[axis];
        q[axis] = h[axis];
        f.edges.emplace_back(p, q);
    }
    f.cornerRadius = box.cornerRadius;
    return f;
}

Features makeMeshFeatures(const ContactShape& mesh) {
    Features f;
    const ConvexPolytope& polytope = *mesh.polytope;
    f.vertices = polytope.getVertices();
    for (const ConvexPolytope::Edge& e : polytope.getEdges()) {
        f.edges.emplace_back(polytope.getVertices()[e.vertex0], polytope.getVertices()[e.vertex1]);
    }
    f.cornerRadius = mesh.cornerRadius;
    return f;
}

// Edge-edge crossings already counted, as (edge of the box, edge of the solid).
using Crossings = std::vector<std::pair<int, int>>;

// One direction: the features of P (posed at X_QP in Q) pressing into solid Q (at X_GQ).
// normalSign is -1 when P is the box (normals from box to solid point into Q), +1 when Q is.
template <class Penetrated>
struct FeaturePass {
    const Features& p;
    const Penetrated& q;
    double qCornerRadius;
    SimTK::Transform X_QP;
    const SimTK::Transform& X_GQ;
    double normalSign;

    void append(const SimTK::Vec3& p_Q, const SimTK::Vec3& n_Q, double depth, double radius,
                std::vector<ContactPoint>& contacts) const {
        ContactPoint contact;
        contact.p_G = X_GQ * p_Q;
        contact.n_G = SimTK::UnitVec3(normalSign * (X_GQ.R() * n_Q), true);
        contact.depth = depth;
        contact.radius = radius;
        contacts.push_back(contact);
    }

    void appendVertexContacts(std::vector<ContactPoint>& contacts) const {
        for (const SimTK::Vec3& v : p.vertices) {
            const SimTK::Vec3 v_Q = X_QP * v;
            const PenetratedSurface s = q.findSurface(v_Q);
            if (s.distance >= 0) continue;
            const double depth = -s.distance;
            append(v_Q + (0.5 * depth) * s.n, s.n, depth,
                   combineRadii(p.cornerRadius, s.curvatureRadius), contacts);
        }
    }

    void appendEdgeContacts(Crossings& crossings, std::vector<ContactPoint>& contacts) const {
        for (std::size_t index = 0; index < p.edges.size(); ++index) {
            const SimTK::Vec3 e0 = X_QP * p.edges[index].first, e1 = X_QP * p.edges[index].second;
            const SimTK::Vec3 d = e1 - e0;
            // Only an edge entering Q can have its deepest point inside.
            if (!q.meetsSegment(e0, e1)) continue;
            const auto distance = [&](double t) { return q.calcDistance(e0 + t * d); };
            const ArgminInterval deepest = findConvexArgminInterval(distance, kFlatTolerance);
            if (deepest.lower <= 0 || deepest.upper >= 1) continue;  // a vertex, counted apart
            const SimTK::Vec3 point = e0 + deepest.middle() * d;
            const PenetratedSurface s = q.findSurface(point);
            if (s.distance >= 0) continue;
            if (s.atEdge && appendCrossing(e0, e1, s, static_cast<int>(index), crossings, contacts)) {
                continue;
            }
            const double depth = -s.distance;
            append(point + (0.5 * depth) * s.n, s.n, depth,
                   combineRadii(p.cornerRadius, s.curvatureRadius), contacts);
        }
    }

    // The exact line-line contact of an edge of P crossing edge s.edge of Q (see box_contact.cpp).
    bool appendCrossing(const SimTK::Vec3& e0, const SimTK::Vec3& e1, const PenetratedSurface& s,
                        int indexP, Crossings& crossings, std::vector<ContactPoint>& contacts) const {
        const SimTK::Vec3 u = e1 - e0, v = s.edge.direction;
        SimTK::Vec3 o = SimTK::cross(u, v);
        if (o.norm() / u.norm() <= 1e-9) return false;
        o /= o.norm();
        if (SimTK::dot(o, s.n) < 0) o = -o;
        const SimTK::Vec3 w = e0 - s.edge.point;
        const double uu = SimTK::dot(u, u), uv = SimTK::dot(u, v), uw = SimTK::dot(u, w),
                     vw = SimTK::dot(v, w);
        const double denominator = uu - uv * uv;
        const SimTK::Vec3 onP = e0 + ((uv * vw - uw) / denominator) * u;
        const SimTK::Vec3 onQ = s.edge.point + ((uu * vw - uv * uw) / denominator) * v;
        const double depth = SimTK::dot(onQ - onP, o);
        if (depth <= 0) return false;
        const std::pair<int, int> key =
            normalSign < 0 ? std::make_pair(indexP, s.edge.index) : std::make_pair(s.edge.index, indexP);
        if (std::find(crossings.begin(), crossings.end(), key) == crossings.end()) {
            crossings.push_back(key);
            append(0.5 * (onP + onQ), o, depth, combineRadii(p.cornerRadius, qCornerRadius), contacts);
        }
        return true;
    }
};

// The deepest point of a cylinder or ellipsoid (at X_BS in the box frame) below box face
// (axis, sign), with its Hertz radius; see box_object_contact.h.
std::pair<SimTK::Vec3, double> findDeepestBelowFace(const ContactShape& box, const ContactShape& solid,
                                                    const SimTK::Transform& X_BS, int axis, int sign) {
    SimTK::Vec3 inward_B(0);
    inward_B[axis] = -sign;
    const SimTK::Vec3 u_S = ~X_BS.R() * inward_B;
    if (solid.type == ContactShape::Type::Ellipsoid) {
        const SimTK::Vec3 p_S = findEllipsoidSupportPoint(solid.semiAxes, u_S);
        return {X_BS * p_S, calcEllipsoidCurvatureRadius(solid.semiAxes, p_S)};
    }
    const double radial = std::hypot(u_S[0], u_S[1]), half = 0.5 * solid.length;
    if (radial <= 1e-12) return {X_BS * SimTK::Vec3(0, 0, u_S[2] > 0 ? half : -half), solid.radius};
    const SimTK::Vec3 side(solid.radius * u_S[0] / radial, solid.radius * u_S[1] / radial, 0);
    const SimTK::Vec3 c0 = X_BS * (side - SimTK::Vec3(0, 0, half)), c1 = X_BS * (side + SimTK::Vec3(0, 0, half));
    const auto distance = [&](double t) { return calcBoxSignedDistance(box.halfLengths, c0 + t * (c1 - c0)); };
    return {c0 + findConvexArgminInterval(distance, kFlatTolerance).middle() * (c1 - c0), solid.radius};
}

void appendSmoothIntoBoxContacts(const ContactShape& box, const SimTK::Transform& X_GB,
                                 const ContactShape& solid, const SimTK::Transform& X_BS,
                                 std::vector<ContactPoint>& contacts) {
    for (int axis = 0; axis < 3; ++axis) {
        for (int sign = -1; sign <= 1; sign += 2) {
            const auto [p_B, radius] = findDeepestBelowFace(box, solid, X_BS, axis, sign);
            const BoxSurfacePoint s = findBoxSurface(box.halfLengths, p_B);
            if (s.distance >= 0 || s.tiedAxes[0] != axis || s.tiedSigns[0] != sign) continue;
            ContactPoint contact;
            contact.depth = -s.distance;
            contact.p_G = X_GB * (p_B + (0.5 * contact.depth) * s.n_S);
            contact.n_G = X_GB.R() * s.n_S;  // the solid presses into the box: box's outward normal
            contact.radius = radius;
            contacts.push_back(contact);
        }
    }
}

}  // namespace

void appendBoxObjectContacts(const ContactShape& box, const SimTK::Transform& X_GB,
                             const ContactShape& solid, const SimTK::Transform& X_GS,
                             std::vector<ContactPoint>& contacts) {
    if ((X_GS.p() - X_GB.p()).norm() >= box.calcBoundingRadius() + solid.calcBoundingRadius()) return;
    const SimTK::Transform X_SB = ~X_GS * X_GB;
    const Features boxFeatures = makeBoxFeatures(box);
    const PenetratedObject penetratedSolid{solid};
    const FeaturePass<PenetratedObject> boxIntoSolid{boxFeatures, penetratedSolid, solid.cornerRadius,
                                                     X_SB, X_GS, -1};
    boxIntoSolid.appendVertexContacts(contacts);
    if (solid.type != ContactShape::Type::ConvexMesh) {
        Crossings none;
        boxIntoSolid.appendEdgeContacts(none, contacts);
        appendSmoothIntoBoxContacts(box, X_GB, solid, ~X_SB, contacts);
        return;
    }
    // Same order as box vs box: vertices of each, then edges of each.
    const Features meshFeatures = makeMeshFeatures(solid);
    const PenetratedBox penetratedBox{box};
    const FeaturePass<PenetratedBox> solidIntoBox{meshFeatures, penetratedBox, box.cornerRadius,
                                                  ~X_SB, X_GB, +1};
    solidIntoBox.appendVertexContacts(contacts);
    Crossings crossings;
    boxIntoSolid.appendEdgeContacts(crossings, contacts);
    solidIntoBox.appendEdgeContacts(crossings, contacts);
}

}  // namespace graspsim::contact
