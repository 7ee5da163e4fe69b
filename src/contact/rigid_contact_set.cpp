#include "graspsim/contact/rigid_contact_set.h"

#include <algorithm>

namespace graspsim::contact {

namespace {

// Not a sphere or capsule: a box, half-space, cylinder, ellipsoid or convex mesh.
bool isSolid(const ContactShape& s) {
    return s.type != ContactShape::Type::Sphere && s.type != ContactShape::Type::Capsule;
}

// The 8 rounded corners of `box`'s surface as spheres inside the corners (see the header).
std::vector<ContactSurface> makeCornerSpheres(const ContactSurface& box) {
    const SimTK::Vec3& h = box.shape.halfLengths;
    const double r = std::min({box.shape.cornerRadius, h[0], h[1], h[2]});
    std::vector<ContactSurface> corners;
    for (int k = 0; k < 8; ++k) {
        const SimTK::Vec3 sign((k & 1) ? 1 : -1, (k & 2) ? 1 : -1, (k & 4) ? 1 : -1);
        ContactSurface corner = box;
        corner.shape = ContactShape::sphere(r);
        const SimTK::Vec3 p_SC(sign[0] * (h[0] - r), sign[1] * (h[1] - r), sign[2] * (h[2] - r));
        corner.X_BS = box.X_BS * SimTK::Transform(p_SC);
        const auto axis = [&](int i) { return std::string(sign[i] > 0 ? "+" : "-"); };
        corner.shapeName = box.shapeName + " corner " + axis(0) + "x" + axis(1) + "y" + axis(2) + "z";
        corners.push_back(corner);
    }
    return corners;
}

}  // namespace

std::vector<ContactPair> makeRigidContactPairs(const ContactPair& pair) {
    if (isRigidContactSupported(pair.a.shape, pair.b.shape)) return {pair};
    std::vector<ContactPair> pairs;
    const auto add = [&](const ContactSurface& a, const ContactSurface& b) {
        ContactPair corner = pair;
        corner.a = a;
        corner.b = b;
        pairs.push_back(corner);
    };
    if (pair.a.shape.type == ContactShape::Type::Box) {
        for (const ContactSurface& c : makeCornerSpheres(pair.a)) add(c, pair.b);
    }
    if (pair.b.shape.type == ContactShape::Type::Box) {
        for (const ContactSurface& c : makeCornerSpheres(pair.b)) add(pair.a, c);
    }
    // Pairs of two solids without a box (two half-spaces, an object solid on a half-space)
    // remain unsupported: RigidContact rejects the pair with its reason.
    if (pairs.empty() && isSolid(pair.a.shape) && isSolid(pair.b.shape)) return {pair};
    return pairs;
}

RigidContactSet::RigidContactSet(SimTK::SimbodyMatterSubsystem& matter, const std::vector<ContactPair>& pairs)
    : matter_(&matter) {
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        for (const ContactPair& p : makeRigidContactPairs(pairs[i])) {
            contacts_.push_back(RigidContact::add(matter, p));
            pairs_.push_back(p);
            pairIndices_.push_back(static_cast<int>(i));
        }
    }
}

const RigidContact& RigidContactSet::getContact(int k) const {
    return dynamic_cast<const RigidContact&>(matter_->getUnilateralContact(contacts_.at(static_cast<std::size_t>(k))));
}

std::vector<ContactReport> RigidContactSet::findContactReports(const SimTK::State& state) const {
    std::vector<ContactReport> reports;
    if (!matter_) return reports;
    matter_->getSystem().realize(state, SimTK::Stage::Velocity);
    const SimTK::Vector& lambda = state.updMultipliers();  // filled by the step; reading does not invalidate
    for (int k = 0; k < getNumContacts(); ++k) {
        if (!getContact(k).isEnabled(state)) continue;
        reports.push_back(makeReport(state, k, lambda));
    }
    return reports;
}

ContactReport RigidContactSet::makeReport(const SimTK::State& state, int k, const SimTK::Vector& lambda) const {
    const RigidContact& contact = getContact(k);
    const ContactPair& pair = pairs_[static_cast<std::size_t>(k)];
    const RigidContactGeometry g = contact.findGeometryInGround(state);
    ContactReport r = makePairReport(pair, pairIndices_[static_cast<std::size_t>(k)]);
    r.p_G = g.p_F;
    r.n_G = g.n_F;
    r.depth = -g.separation;
    r.depthRate = -contact.getVerr(state);
    // The friction basis of RigidContact::getSlipVelocity() and of the constraint's forces.
    const SimTK::UnitVec3 tx = g.n_F.perp();
    const SimTK::Vec3 ty = g.n_F % tx;
    const SimTK::Vec2 slip = contact.getSlipVelocity(state);
    r.slipVelocity_G = slip[0] * SimTK::Vec3(tx) + slip[1] * ty;
    const SimTK::MultiplierIndex n = contact.getContactMultiplierIndex(state);
    SimTK::MultiplierIndex fx, fy;
    contact.getFrictionMultiplierIndices(state, fx, fy);
    if (n.isValid() && n < lambda.size()) r.normalForce = -lambda[n];
    if (fx.isValid() && fy.isValid() && fy < lambda.size()) r.frictionForce_G = -(lambda[fx] * SimTK::Vec3(tx) + lambda[fy] * ty);
    return r;
}

}  // namespace graspsim::contact
