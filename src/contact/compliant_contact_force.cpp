#include "graspsim/contact/compliant_contact_force.h"

#include <algorithm>
#include <numeric>

#include <string>
#include <utility>

#include "graspsim/contact/anchor_friction.h"
#include "graspsim/contact/contact_force_law.h"
#include "graspsim/contact/shape_contact.h"
#include "graspsim/error.h"

namespace graspsim::contact {

namespace {

using EnabledFlags = std::vector<bool>;

// Z variables per pair with anchors: the deflection z (3, in body a's frame) and sigma.
constexpr int kAnchorSize = 4;

// A pair with its parameters next to it (validated once, at construction).
struct PreparedPair {
    ContactPair pair;
    ContactParameters parameters;
};

// The kinematics of one body as a contact needs them, read once per pair.
struct BodyMotion {
    SimTK::Vec3 p_GBo;       // body origin in Ground (m)
    SimTK::SpatialVec V_GB;  // angular (rad/s) and origin linear (m/s) velocity, in Ground

    SimTK::Vec3 findPointVelocity(const SimTK::Vec3& p_GP) const {
        return V_GB[1] + V_GB[0] % (p_GP - p_GBo);
    }
};

BodyMotion findBodyMotion(const SimTK::State& state, const SimTK::MobilizedBody& body) {
    return {body.getBodyOriginLocation(state), body.getBodyVelocity(state)};
}

// Normal and friction forces of one contact point (on body b; a gets the opposite).
struct ContactForce {
    double depthRate = 0;
    SimTK::Vec3 slipVelocity_G{0, 0, 0};
    double normalForce = 0;
    SimTK::Vec3 frictionForce_G{0, 0, 0};
};

ContactForce calcContactForce(const ContactParameters& parameters, const ContactPoint& contact,
                              const BodyMotion& a, const BodyMotion& b) {
    const SimTK::Vec3 v = b.findPointVelocity(contact.p_G) - a.findPointVelocity(contact.p_G);
    const double vNormal = SimTK::dot(v, contact.n_G);
    ContactForce force;
    force.depthRate = -vNormal;  // b moving toward a (against n) deepens the contact
    force.slipVelocity_G = v - vNormal * contact.n_G;
    force.normalForce = calcNormalForce(parameters, contact.radius, contact.depth, force.depthRate);
    return force;
}

// The anchor's view of a pair's contact points (anchor_friction.h), with each point's share of
// the pair's friction (stiffness weights, summing to 1) in `weights`.
AnchorContact makeAnchorContact(const ContactParameters& parameters, const AnchorFrictionParameters& anchor,
                                const std::vector<ContactPoint>& contacts, const std::vector<ContactForce>& forces,
                                const BodyMotion& a, const BodyMotion& b, std::vector<double>& weights) {
    AnchorContact pair;
    weights.clear();
    SimTK::Vec3 n(0), v(0);
    for (std::size_t k = 0; k < contacts.size(); ++k) {
        const double stiffness = calcAnchorStiffness(parameters, anchor, contacts[k].radius, contacts[k].depth);
        weights.push_back(stiffness);
        pair.stiffness += stiffness;
        pair.normalForce += forces[k].normalForce;
        n += stiffness * contacts[k].n_G.asVec3();
        v += stiffness * (b.findPointVelocity(contacts[k].p_G) - a.findPointVelocity(contacts[k].p_G));
    }
    for (double& w : weights) w /= pair.stiffness;
    // Opposed normals cancelling (not met with convex shapes) fall back on the first point's.
    pair.n_G = n.normSqr() > 0 ? SimTK::UnitVec3(n) : contacts.front().n_G;
    v /= pair.stiffness;  // the relative velocity at the weighted centre (it is affine in the point)
    pair.slipVelocity_G = v - SimTK::dot(v, pair.n_G) * pair.n_G;
    return pair;
}

// Adds force F (N, in G) applied at point p_G to body `body`'s entry of bodyForces.
void applyForceAtPoint(const SimTK::MobilizedBody& body, const BodyMotion& motion,
                       const SimTK::Vec3& p_G, const SimTK::Vec3& F_G,
                       SimTK::Vector_<SimTK::SpatialVec>& bodyForces) {
    SimTK::SpatialVec& entry = bodyForces[body.getMobilizedBodyIndex()];
    entry[0] += (p_G - motion.p_GBo) % F_G;
    entry[1] += F_G;
}

// Per-thread scratch for the contact points of one pair. Force evaluation is the hot path
// (every integrator stage); reusing one buffer avoids a heap allocation per pair and call.
// Thread-local rather than a member because one system may be evaluated from several threads
// with different states.
std::vector<ContactPoint>& updScratchContacts() {
    thread_local std::vector<ContactPoint> contacts;
    contacts.clear();
    return contacts;
}

// The same for the forces of those points and their friction shares.
std::vector<ContactForce>& updScratchForces() {
    thread_local std::vector<ContactForce> forces;
    forces.clear();
    return forces;
}
std::vector<double>& updScratchWeights() {
    thread_local std::vector<double> weights;
    return weights;
}

}  // namespace

class CompliantContactForceImpl : public SimTK::Force::Custom::Implementation {
public:
    CompliantContactForceImpl(const SimTK::GeneralForceSubsystem& forces,
                              std::vector<ContactPair> pairs, const FrictionSettings& friction)
        : forces_(forces), friction_(friction) {
        if (friction.model == FrictionModel::Anchor) friction.anchor.validate("compliant contact friction");
        pairs_.reserve(pairs.size());
        for (ContactPair& pair : pairs) {
            const std::string name = "contact pair '" + pair.describe() + "'";
            pair.parameters.validate(name);
            if (pair.a.shape.type == ContactShape::Type::HalfSpace &&
                pair.b.shape.type == ContactShape::Type::HalfSpace) {
                throw InputError(name + ": two half-spaces cannot be a contact pair");
            }
            pair.a.shape.validate(name + " shape a");
            pair.b.shape.validate(name + " shape b");
            const ContactParameters parameters = pair.parameters;
            pairs_.push_back({std::move(pair), parameters});
        }
    }

    int getNumPairs() const { return static_cast<int>(pairs_.size()); }
    const ContactPair& getPair(int i) const { return pairs_.at(i).pair; }
    const FrictionSettings& getFrictionSettings() const { return friction_; }
    bool hasAnchors() const { return friction_.model == FrictionModel::Anchor; }

    const EnabledFlags& getEnabledFlags(const SimTK::State& state) const {
        return SimTK::Value<EnabledFlags>::downcast(
                   forces_.getDiscreteVariable(state, enabledIndex_))
            .get();
    }
    EnabledFlags& updEnabledFlags(SimTK::State& state) const {
        return SimTK::Value<EnabledFlags>::updDowncast(
                   forces_.updDiscreteVariable(state, enabledIndex_))
            .upd();
    }

    // Pair i's anchor deflection z (m) in its body a's frame; zero without anchors.
    SimTK::Vec3 getAnchorDeflection(const SimTK::State& state, int i) const {
        if (!hasAnchors()) return SimTK::Vec3(0);
        const SimTK::Vector& z = forces_.getZ(state);
        const int k = zStart_ + kAnchorSize * i;
        return {z[k], z[k + 1], z[k + 2]};
    }
    double getAnchorSliding(const SimTK::State& state, int i) const {
        return hasAnchors() ? forces_.getZ(state)[zStart_ + kAnchorSize * i + 3] : 0.0;
    }

    void realizeTopology(SimTK::State& state) const override {
        EnabledFlags defaults;
        for (const PreparedPair& p : pairs_) defaults.push_back(p.pair.enabledByDefault);
        enabledIndex_ = forces_.allocateDiscreteVariable(state, SimTK::Stage::Instance,
                                                         new SimTK::Value<EnabledFlags>(defaults));
        if (hasAnchors()) zStart_ = forces_.allocateZ(state, SimTK::Vector(kAnchorSize * getNumPairs(), 0.0));
        evaluatedIndex_ = forces_.allocateLazyCacheEntry(state, SimTK::Stage::Velocity,
                                                         new SimTK::Value<std::vector<ContactReport>>());
    }

    // Also sets the anchors' rates: calcForce is called while the State is realized to
    // Stage::Dynamics, where Z derivatives are written, for every evaluation of an enabled element.
    // The contact points are kept in a cache entry (getEvaluatedContacts) as they are evaluated:
    // the linearly implicit stepper's Jacobian needs the same geometry, which was a second pass.
    void calcForce(const SimTK::State& state, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                   SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const override {
        const EnabledFlags& enabled = getEnabledFlags(state);
        std::vector<ContactReport>& evaluated = updEvaluatedCache(state);
        evaluated.clear();
        for (int i = 0; i < getNumPairs(); ++i) {
            AnchorState rate;
            if (enabled[i]) {
                forEachPairForce(state, i, rate, [&](const ContactPoint& contact, const ContactForce& force,
                                                                 const BodyMotion& a, const BodyMotion& b) {
                    const SimTK::Vec3 F_G = force.normalForce * contact.n_G + force.frictionForce_G;
                    applyForceAtPoint(pairs_[i].pair.a.body, a, contact.p_G, -F_G, bodyForces);
                    applyForceAtPoint(pairs_[i].pair.b.body, b, contact.p_G, F_G, bodyForces);
                    evaluated.push_back(makeUnnamedReport(i, contact, force));
                });
            } else if (hasAnchors()) {
                rate = calcAnchorRelaxationRate(friction_.anchor, getAnchorState(state, i));
            }
            if (hasAnchors()) setAnchorRate(state, i, rate);
        }
        forces_.markCacheValueRealized(state, evaluatedIndex_);
    }

    // The cache written by calcForce, or, where no force evaluation filled it at this state's
    // positions and velocities (the element disabled, or the state realized only to Velocity),
    // the same computed here.
    const std::vector<ContactReport>& getEvaluatedContacts(const SimTK::State& state) const {
        if (!forces_.isCacheValueRealized(state, evaluatedIndex_)) {
            std::vector<ContactReport>& evaluated = updEvaluatedCache(state);
            evaluated.clear();
            const EnabledFlags& enabled = getEnabledFlags(state);
            for (int i = 0; i < getNumPairs(); ++i) {
                if (!enabled[i]) continue;
                AnchorState unused;
                forEachPairForce(state, i, unused, [&](const ContactPoint& contact, const ContactForce& force,
                                                       const BodyMotion&, const BodyMotion&) {
                    evaluated.push_back(makeUnnamedReport(i, contact, force));
                });
            }
            forces_.markCacheValueRealized(state, evaluatedIndex_);
        }
        return SimTK::Value<std::vector<ContactReport>>::downcast(forces_.getCacheEntry(state, evaluatedIndex_)).get();
    }

    SimTK::Real calcPotentialEnergy(const SimTK::State& state) const override {
        double energy = 0;
        const EnabledFlags& enabled = getEnabledFlags(state);
        for (int i = 0; i < getNumPairs(); ++i) {
            if (!enabled[i]) continue;
            for (const ContactPoint& contact : findPairContacts(state, i)) {
                energy += calcHertzEnergy(pairs_[i].parameters, contact.radius, contact.depth);
            }
        }
        return energy;
    }

    std::vector<ContactReport> findContactReports(const SimTK::State& state) const {
        const EnabledFlags& enabled = getEnabledFlags(state);
        return findReports(state, [&](int i) { return bool(enabled[i]); });
    }

    // The listed pairs, whatever their flags say.
    std::vector<ContactReport> findContactReports(const SimTK::State& state, const std::vector<int>& pairIndices) const {
        return findReports(state, [&](int i) {
            return std::find(pairIndices.begin(), pairIndices.end(), i) != pairIndices.end();
        });
    }

    std::vector<ContactDepth> findContactDepths(const SimTK::State& state, const std::vector<int>& pairIndices) const {
        std::vector<ContactDepth> depths;
        for (int i = 0; i < getNumPairs(); ++i) {
            if (std::find(pairIndices.begin(), pairIndices.end(), i) == pairIndices.end()) continue;
            for (const ContactPoint& contact : findPairContacts(state, i)) depths.push_back({i, contact.depth});
        }
        return depths;
    }

private:
    // The contact points of pair i in the scratch buffer (valid until the next call).
    const std::vector<ContactPoint>& findPairContacts(const SimTK::State& state, int i) const {
        const ContactPair& pair = pairs_[i].pair;
        std::vector<ContactPoint>& contacts = updScratchContacts();
        appendContacts(pair.a.shape, pair.a.body.getBodyTransform(state) * pair.a.X_BS,
                       pair.b.shape, pair.b.body.getBodyTransform(state) * pair.b.X_BS, contacts,
                       pairs_[i].parameters.capsuleContact);
        return contacts;
    }

    // Pair i's anchor with its deflection in Ground.
    AnchorState getAnchorState(const SimTK::State& state, int i) const {
        return {pairs_[i].pair.a.body.getBodyRotation(state) * getAnchorDeflection(state, i),
                getAnchorSliding(state, i)};
    }

    void setAnchorRate(const SimTK::State& state, int i, const AnchorState& rate) const {
        const SimTK::Vec3 rate_A = ~pairs_[i].pair.a.body.getBodyRotation(state) * rate.deflection_G;
        SimTK::Vector& zDot = forces_.updZDot(state);
        const int first = zStart_ + kAnchorSize * i;
        for (int k = 0; k < 3; ++k) zDot[first + k] = rate_A[k];
        zDot[first + 3] = rate.sliding;
    }

    // Calls visit(contact, force, motionA, motionB) for every contact point of pair i with its
    // normal and friction forces, and sets `rate` to the pair anchor's rate (its relaxation
    // when the pair has no contact; untouched for the regularized law).
    template <class Visit>
    void forEachPairForce(const SimTK::State& state, int i, AnchorState& rate, Visit&& visit) const {
        const std::vector<ContactPoint>& contacts = findPairContacts(state, i);
        if (contacts.empty()) {
            if (hasAnchors()) rate = calcAnchorRelaxationRate(friction_.anchor, getAnchorState(state, i));
            return;
        }
        const ContactParameters& parameters = pairs_[i].parameters;
        const BodyMotion a = findBodyMotion(state, pairs_[i].pair.a.body);
        const BodyMotion b = findBodyMotion(state, pairs_[i].pair.b.body);
        std::vector<ContactForce>& forces = updScratchForces();
        for (const ContactPoint& contact : contacts) forces.push_back(calcContactForce(parameters, contact, a, b));
        if (hasAnchors()) {
            std::vector<double>& weights = updScratchWeights();
            const AnchorContact pair = makeAnchorContact(parameters, friction_.anchor, contacts, forces, a, b, weights);
            const AnchorFriction friction =
                calcAnchorFriction(parameters, friction_.anchor, pair, getAnchorState(state, i));
            for (std::size_t k = 0; k < forces.size(); ++k) forces[k].frictionForce_G = weights[k] * friction.force_G;
            rate = friction.rate;
        } else {
            for (ContactForce& force : forces) {
                force.frictionForce_G = calcFrictionForce(parameters, force.normalForce, force.slipVelocity_G);
            }
        }
        for (std::size_t k = 0; k < forces.size(); ++k) visit(contacts[k], forces[k], a, b);
    }

    template <class Selected>
    std::vector<ContactReport> findReports(const SimTK::State& state, Selected&& selected) const {
        std::vector<ContactReport> reports;
        for (int i = 0; i < getNumPairs(); ++i) {
            if (!selected(i)) continue;
            AnchorState unused;
            forEachPairForce(state, i, unused, [&](const ContactPoint& contact, const ContactForce& force,
                                                   const BodyMotion&, const BodyMotion&) {
                reports.push_back(makeReport(i, contact, force));
            });
        }
        return reports;
    }

    std::vector<ContactReport>& updEvaluatedCache(const SimTK::State& state) const {
        return SimTK::Value<std::vector<ContactReport>>::updDowncast(forces_.updCacheEntry(state, evaluatedIndex_)).upd();
    }

    ContactReport makeReport(int i, const ContactPoint& contact, const ContactForce& force) const {
        ContactReport report = makeUnnamedReport(i, contact, force);
        const ContactPair& pair = pairs_[i].pair;
        report.bodyA = pair.a.bodyName;
        report.bodyB = pair.b.bodyName;
        report.shapeA = pair.a.shapeName;
        report.shapeB = pair.b.shapeName;
        return report;
    }

    static ContactReport makeUnnamedReport(int i, const ContactPoint& contact, const ContactForce& force) {
        ContactReport report;
        report.pairIndex = i;
        report.p_G = contact.p_G;
        report.n_G = contact.n_G;
        report.depth = contact.depth;
        report.radius = contact.radius;
        report.depthRate = force.depthRate;
        report.slipVelocity_G = force.slipVelocity_G;
        report.normalForce = force.normalForce;
        report.frictionForce_G = force.frictionForce_G;
        return report;
    }

    const SimTK::GeneralForceSubsystem& forces_;
    std::vector<PreparedPair> pairs_;
    FrictionSettings friction_;
    mutable SimTK::DiscreteVariableIndex enabledIndex_;
    mutable SimTK::ZIndex zStart_;
    mutable SimTK::CacheEntryIndex evaluatedIndex_;
};

namespace {

const CompliantContactForceImpl& asContactImpl(const SimTK::Force::Custom::Implementation& impl) {
    return static_cast<const CompliantContactForceImpl&>(impl);
}

}  // namespace

CompliantContactForce::CompliantContactForce(SimTK::GeneralForceSubsystem& forces,
                                             std::vector<ContactPair> pairs)
    : CompliantContactForce(forces, std::move(pairs), FrictionSettings()) {}

CompliantContactForce::CompliantContactForce(SimTK::GeneralForceSubsystem& forces, std::vector<ContactPair> pairs,
                                             const FrictionSettings& friction)
    : SimTK::Force::Custom(forces, new CompliantContactForceImpl(forces, std::move(pairs), friction)) {}

const FrictionSettings& CompliantContactForce::getFrictionSettings() const {
    return asContactImpl(getImplementation()).getFrictionSettings();
}

SimTK::Vec3 CompliantContactForce::getAnchorDeflection(const SimTK::State& state, int pairIndex) const {
    checkPairIndex(pairIndex);
    return asContactImpl(getImplementation()).getAnchorDeflection(state, pairIndex);
}

void CompliantContactForce::checkPairIndex(int pairIndex) const {
    const int count = getNumPairs();
    if (pairIndex < 0 || pairIndex >= count) {
        throw InputError("contact pair index " + std::to_string(pairIndex) +
                         " is out of range; the element has " + std::to_string(count) +
                         " pairs (0 to " + std::to_string(count - 1) + ")");
    }
}

int CompliantContactForce::getNumPairs() const {
    return asContactImpl(getImplementation()).getNumPairs();
}

std::vector<int> CompliantContactForce::findAllPairIndices() const {
    std::vector<int> pairs(static_cast<std::size_t>(getNumPairs()));
    std::iota(pairs.begin(), pairs.end(), 0);
    return pairs;
}

const ContactPair& CompliantContactForce::getPair(int pairIndex) const {
    checkPairIndex(pairIndex);
    return asContactImpl(getImplementation()).getPair(pairIndex);
}

bool CompliantContactForce::isPairEnabled(const SimTK::State& state, int pairIndex) const {
    checkPairIndex(pairIndex);
    return asContactImpl(getImplementation()).getEnabledFlags(state)[pairIndex];
}

void CompliantContactForce::setPairEnabled(SimTK::State& state, int pairIndex, bool enabled) const {
    setPairsEnabled(state, {pairIndex}, enabled);
}

void CompliantContactForce::setPairsEnabled(SimTK::State& state,
                                            const std::vector<int>& pairIndices,
                                            bool enabled) const {
    for (int i : pairIndices) checkPairIndex(i);
    EnabledFlags& flags = asContactImpl(getImplementation()).updEnabledFlags(state);
    for (int i : pairIndices) flags[i] = enabled;
}

double sumNormalForces(const std::vector<ContactReport>& reports) {
    double sum = 0;
    for (const ContactReport& r : reports) sum += r.normalForce;
    return sum;
}

ContactReport makePairReport(const ContactPair& pair, int pairIndex) {
    ContactReport report;
    report.pairIndex = pairIndex;
    report.bodyA = pair.a.bodyName;
    report.bodyB = pair.b.bodyName;
    report.shapeA = pair.a.shapeName;
    report.shapeB = pair.b.shapeName;
    return report;
}

std::vector<ContactReport> CompliantContactForce::findContactReports(const SimTK::State& state,
                                                                   const std::vector<int>& pairIndices) const {
    for (int i : pairIndices) checkPairIndex(i);
    return asContactImpl(getImplementation()).findContactReports(state, pairIndices);
}

std::vector<ContactDepth> CompliantContactForce::findContactDepths(const SimTK::State& state,
                                                                  const std::vector<int>& pairIndices) const {
    for (int i : pairIndices) checkPairIndex(i);
    return asContactImpl(getImplementation()).findContactDepths(state, pairIndices);
}

const std::vector<ContactReport>& CompliantContactForce::getEvaluatedContacts(const SimTK::State& state) const {
    return asContactImpl(getImplementation()).getEvaluatedContacts(state);
}

std::vector<ContactReport> CompliantContactForce::findContactReports(
    const SimTK::State& state) const {
    return asContactImpl(getImplementation()).findContactReports(state);
}

}  // namespace graspsim::contact
