#include "graspsim/simulation/grasp_switch.h"

#include "graspsim/error.h"
#include "graspsim/simulation/bushing_give.h"
#include "graspsim/grasp/limited_bushing_law.h"
#include "graspsim/simulation/compliance_release.h"
#include "graspsim/simulation/contact_grasp_quality.h"
#include "graspsim/simulation/deflected_hand_back.h"
#include "graspsim/simulation/multi_attachment_switch.h"
#include "graspsim/system/simtk_conversion.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace graspsim::simulation {

namespace {

// How far (m) the locked fingers must be able to move their pads toward the give's targets before
// they are moved: moving them re-initializes the integrator, and 10 um is a hundredth of the pads'
// compression under the grip (1-2.6 mm).
constexpr double kFollowTolerance = 1e-5;

std::string format(const char* pattern, double a, double b = 0) {
    char buffer[160];
    std::snprintf(buffer, sizeof buffer, pattern, a, b);
    return buffer;
}

// Eq. 4.1-4.3: F_perp = sum f_i . n_i; r = mean distance of the contact points to their centroid.
// Returns the constraint's limits, rotation first: mu r F_perp (N m), then mu F_perp (N).
SimTK::Vec6 calcFrictionLimits(const std::vector<contact::ContactReport>& reports, double mu) {
    double fPerp = 0;
    SimTK::Vec3 centroid(0);
    for (const contact::ContactReport& c : reports) {
        const SimTK::Vec3 f = c.normalForce * SimTK::Vec3(c.n_G) + c.frictionForce_G;
        fPerp += ~f * SimTK::Vec3(c.n_G);
        centroid += c.p_G;
    }
    centroid /= static_cast<double>(reports.size());
    double r = 0;
    for (const contact::ContactReport& c : reports) r += (c.p_G - centroid).norm();
    r /= static_cast<double>(reports.size());
    const double linear = mu * fPerp, angular = mu * r * fPerp;
    return SimTK::Vec6(angular, angular, angular, linear, linear, linear);
}

// The per-axis limits of the constraint frame M (orientation R_GM, origin p_GM) from each contact's
// normal and position (grasp/friction_limits.h), rotation first as calcFrictionLimits.
SimTK::Vec6 calcContactGeometryLimits(const std::vector<contact::ContactReport>& reports, double mu,
                                      const SimTK::Rotation& R_GM, const SimTK::Vec3& p_GM) {
    std::vector<grasp::GraspContact> contacts;
    for (const contact::ContactReport& c : reports) {
        grasp::GraspContact g;
        g.p_GC = system::toEigenVector(c.p_G);
        g.n_G = system::toEigenVector(SimTK::Vec3(c.n_G));
        g.normalForce = c.normalForce;
        contacts.push_back(g);
    }
    const Eigen::Matrix<double, 6, 1> limits =
        grasp::calcContactGeometryLimits(contacts, mu, system::toEigenMatrix(R_GM), system::toEigenVector(p_GM));
    SimTK::Vec6 result;
    for (int k = 0; k < 6; ++k) result[k] = limits[k];
    return result;
}

// " [-L-, L+] N, ..." for the six axes, translation first (the engage event's text).
std::string describeTwoSided(const SimTK::Vec6& lower, const SimTK::Vec6& upper) {
    std::string text;
    for (int k : {3, 4, 5, 0, 1, 2}) text += format(" [-%.6g, %.6g]", lower[k], upper[k]) + (k == 5 ? " N," : k == 2 ? " N m" : "");
    return text;
}

// The friction coefficient of limits computed from the contacts: static or dynamic as the options
// ask (--limits-friction), else static where `staticByDefault`.
double findLimitFriction(const contact::ContactParameters& pair, const ApproxOptions& options, bool staticByDefault) {
    return options.staticFrictionLimits.value_or(staticByDefault) ? pair.staticFriction : pair.dynamicFriction;
}

// Centroid of the contact points (Ground, m): where the friction acts, so where the constraint does.
SimTK::Vec3 findContactCentroid(const std::vector<contact::ContactReport>& reports) {
    SimTK::Vec3 centroid(0);
    for (const contact::ContactReport& c : reports) centroid += c.p_G;
    return centroid / static_cast<double>(reports.size());
}

// The farthest contact point from the constraint frame's origin p_GC (m): the lever arm through
// which a rotation of the object in the hand moves a fingertip into it.
double findLeverArm(const std::vector<contact::ContactReport>& reports, const SimTK::Vec3& p_GC) {
    double arm = 0;
    for (const contact::ContactReport& c : reports) arm = std::max(arm, (c.p_G - p_GC).norm());
    return arm;
}

}  // namespace

std::string toString(GraspEventKind kind) {
    switch (kind) {
    case GraspEventKind::Engage: return "engage";
    case GraspEventKind::Release: return "release";
    case GraspEventKind::Detach: return "detach";
    }
    throw Error("grasp event: unknown kind " + std::to_string(static_cast<int>(kind)));
}

// Keeps the switch's record in the State: a force element that applies no force, there only to
// allocate the record (a Report-stage discrete variable).
class GraspSwitch::RecordKeeper : public SimTK::Force::Custom::Implementation {
public:
    RecordKeeper(const SimTK::GeneralForceSubsystem& forces, GraspSwitchRecord initial)
        : forces_(forces), initial_(std::move(initial)) {}

    void realizeTopology(SimTK::State& state) const override {
        recordIndex_ = forces_.allocateDiscreteVariable(state, SimTK::Stage::Report, new SimTK::Value<GraspSwitchRecord>(initial_));
        // Valid until the time, q, u or an Instance-stage flag changes: exactly what the engaged
        // quality is a function of (with the tracked contacts, which change only at engagement).
        qualityIndex_ = forces_.allocateLazyCacheEntry(state, SimTK::Stage::Velocity, new SimTK::Value<double>(0));
    }
    const GraspSwitchRecord& getRecord(const SimTK::State& state) const {
        return SimTK::Value<GraspSwitchRecord>::downcast(forces_.getDiscreteVariable(state, recordIndex_)).get();
    }
    GraspSwitchRecord& updRecord(SimTK::State& state) const {
        return SimTK::Value<GraspSwitchRecord>::updDowncast(forces_.updDiscreteVariable(state, recordIndex_)).upd();
    }

    /// The engaged quality already computed for `state`, or nullptr.
    const double* findEngagedQuality(const SimTK::State& state) const {
        if (!forces_.isCacheValueRealized(state, qualityIndex_)) return nullptr;
        return &SimTK::Value<double>::downcast(forces_.getCacheEntry(state, qualityIndex_)).get();
    }
    /// Keeps `quality` with `state` (a cache entry: the State is const). Needs Stage::Velocity.
    void setEngagedQuality(const SimTK::State& state, double quality) const {
        SimTK::Value<double>::updDowncast(forces_.updCacheEntry(state, qualityIndex_)).upd() = quality;
        forces_.markCacheValueRealized(state, qualityIndex_);
    }

    void calcForce(const SimTK::State&, SimTK::Vector_<SimTK::SpatialVec>&, SimTK::Vector_<SimTK::Vec3>&,
                   SimTK::Vector&) const override {}
    SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }

private:
    const SimTK::GeneralForceSubsystem& forces_;
    GraspSwitchRecord initial_;
    // Set once, at realizeTopology, where Simbody hands a const element the State to allocate in:
    // Simbody's own pattern for indices (no state of the simulation lives here).
    mutable SimTK::DiscreteVariableIndex recordIndex_;
    mutable SimTK::CacheEntryIndex qualityIndex_;
};

GraspSwitch::GraspSwitch(const ApproximationContext& context, SimTK::GeneralForceSubsystem& forces,
                         const ApproxOptions& options)
    : SimTK::PeriodicEventHandler(context.ikInterval), context_(context), options_(options) {
    GraspSwitchRecord initial{options_.qThreshold, 0, SimTK::Transform(), {}, EngagedGraspTracker(context), std::nullopt, {}};
    initial.qMinimum = options_.qMinimum > 0 ? options_.qMinimum : options_.hysteresisFraction * initial.qThreshold;
    auto* keeper = new RecordKeeper(forces, std::move(initial));
    SimTK::Force::Custom(forces, keeper);
    keeper_ = keeper;
    const model::ModelDescription& d = context.model.getDescription();
    for (const std::string& e : context.goals.getEndEffectors()) goalBodies_.push_back(d.findEndEffector(e)->body);
    if (context.multi) multi_ = std::make_unique<MultiAttachmentSwitch>(context, options.releaseSlideDistance, options.maxEngagedPenetration);
}

GraspSwitch::~GraspSwitch() = default;

const GraspSwitchRecord& GraspSwitch::getRecord(const SimTK::State& state) const { return keeper_->getRecord(state); }
GraspSwitchRecord& GraspSwitch::updRecord(SimTK::State& state) const { return keeper_->updRecord(state); }

// See makeDetachWitness(). Velocity stage: the parts' forces depend on the relative velocity.
class GraspSwitch::DetachWitness : public SimTK::TriggeredEventHandler {
public:
    explicit DetachWitness(const GraspSwitch& grasp) : SimTK::TriggeredEventHandler(SimTK::Stage::Velocity), grasp_(grasp) {
        getTriggerInfo().setTriggerOnRisingSignTransition(false);
        getTriggerInfo().setTriggerOnFallingSignTransition(true);
    }

    SimTK::Real getValue(const SimTK::State& state) const override {
        const double pressing = grasp_.multi_->findSmallestPressing(state);
        return pressing == SimTK::Infinity ? 1.0 : pressing;
    }

    void handleEvent(SimTK::State& state, SimTK::Real, bool& shouldTerminate) const override {
        shouldTerminate = false;
        if (grasp_.isEngaged(state)) grasp_.checkRelease(state);
    }

private:
    const GraspSwitch& grasp_;
};

SimTK::TriggeredEventHandler* GraspSwitch::makeDetachWitness() const { return multi_ ? new DetachWitness(*this) : nullptr; }

// See makeReleaseWitness(). Velocity stage: the bushing's reaction depends on the relative velocity.
class GraspSwitch::ReleaseWitness : public SimTK::TriggeredEventHandler {
public:
    explicit ReleaseWitness(const GraspSwitch& grasp) : SimTK::TriggeredEventHandler(SimTK::Stage::Velocity), grasp_(grasp) {
        getTriggerInfo().setTriggerOnRisingSignTransition(false);
        getTriggerInfo().setTriggerOnFallingSignTransition(true);
    }

    SimTK::Real getValue(const SimTK::State& state) const override {
        const std::optional<ComplianceReleaseLimits>& limits = grasp_.getRecord(state).releaseLimits;
        if (!limits || !grasp_.isEngaged(state)) return 1.0;
        const double margin = findLimitMargin(grasp_.findReactionInO(state), *limits);
        const std::optional<SimTK::Vec6> carried = grasp_.findCarriedLoadInO(state);
        return carried ? std::min(margin, findLimitMargin(*carried, *limits)) : margin;
    }

    void handleEvent(SimTK::State& state, SimTK::Real, bool& shouldTerminate) const override {
        shouldTerminate = false;
        if (grasp_.isEngaged(state)) grasp_.checkRelease(state);
    }

private:
    const GraspSwitch& grasp_;
};

SimTK::TriggeredEventHandler* GraspSwitch::makeReleaseWitness() const {
    return !multi_ && options_.releaseTrigger == ApproxReleaseTrigger::Compliance ? new ReleaseWitness(*this) : nullptr;
}

bool GraspSwitch::isEngaged(const SimTK::State& state) const { return context_.attachment.isEngaged(state); }

void GraspSwitch::handleEvent(SimTK::State& state, SimTK::Real accuracy, bool& shouldTerminate) const {
    shouldTerminate = false;
    if (isEngaged(state)) {
        checkRelease(state);  // IK paused: the fingers are locked to the palm
        return;
    }
    context_.controller.handleEvent(state, accuracy, shouldTerminate);
    if (!context_.hold.isHeld(state)) checkEngage(state);  // only once the object is released
}

double GraspSwitch::calcQuality(const SimTK::State& state) const {
    context_.model.getSystem().realize(state, SimTK::Stage::Velocity);
    return calcQualityOf(state, context_.contacts.findContactReports(state));
}

double GraspSwitch::calcQualityOf(const SimTK::State& state, const std::vector<contact::ContactReport>& reports) const {
    return calcContactGraspQuality(reports, context_.object.getBodyTransform(state),
                                   makeQualityOptions(context_.contactParameters));
}

double GraspSwitch::calcEngagedQuality(const SimTK::State& state) const {
    if (const double* known = keeper_->findEngagedQuality(state)) return *known;
    double q = 0;
    if (!multi_) {
        q = getRecord(state).tracker.calcQuality(state);
    } else {
        // Multi: the fingers move on their own and the palm-fixed tracker does not apply; Q is that
        // of the contacts every pair would produce in `state`, switched on or not.
        context_.model.getSystem().realize(state, SimTK::Stage::Velocity);
        q = calcQualityOf(state, context_.contacts.findContactReports(state, context_.contacts.findAllPairIndices()));
    }
    if (state.getSystemStage() >= SimTK::Stage::Velocity) keeper_->setEngagedQuality(state, q);
    return q;
}

bool GraspSwitch::isFullContact(const std::vector<contact::ContactReport>& reports) const {
    return std::all_of(goalBodies_.begin(), goalBodies_.end(), [&](const std::string& body) {
        return std::any_of(reports.begin(), reports.end(), [&](const contact::ContactReport& c) { return c.bodyA == body; });
    });
}

// A constraint that starts out sticking is only right for an object that is not sliding: with
// regularized friction a contact inside its cone creeps slower than the transition velocity, one
// at its limit slides faster. Without this, an object already slipping out (phone-pinch f1 after a
// release) was re-engaged and dragged through the locked fingertips.
bool GraspSwitch::isSticking(const std::vector<contact::ContactReport>& reports) const {
    if (multi_) return multi_->isSticking(reports);
    const double limit = context_.contactParameters.transitionVelocity;
    return std::all_of(reports.begin(), reports.end(),
                       [&](const contact::ContactReport& c) { return c.slipVelocity_G.norm() < limit; });
}

// One set of contact reports serves every test of the check and the engagement itself.
void GraspSwitch::checkEngage(SimTK::State& state) const {
    context_.model.getSystem().realize(state, SimTK::Stage::Velocity);
    const std::vector<contact::ContactReport> reports = context_.contacts.findContactReports(state);
    if (!isFullContact(reports)) return;
    const double q = calcQualityOf(state, reports);
    if (getRecord(state).qThreshold == 0) {
        // Automatic Q_Th from the first full-contact check once the grasp has settled.
        if (state.getTime() < context_.settleTime - 1e-12) return;
        GraspSwitchRecord& record = updRecord(state);
        record.qThreshold = options_.autoThresholdFraction * q;
        if (options_.qMinimum == 0) record.qMinimum = options_.hysteresisFraction * record.qThreshold;
        // A given Q_M at or above it would release every engagement at once, and the run would chatter.
        if (!(record.qMinimum < record.qThreshold)) {
            char text[320];
            std::snprintf(text, sizeof text,
                          "Q_M (--q-minimum or approximation.q_minimum) %.6g N is not accepted: it must be below Q_Th, "
                          "here automatic, %.6g N (%g x the settled grasp's quality); give a smaller Q_M or a --q-threshold "
                          "above it", record.qMinimum, record.qThreshold, options_.autoThresholdFraction);
            throw InputError(text);
        }
    }
    if (!isSticking(reports)) return;
    // Not at the instant of a release (a witness may release at a check's time): the contacts just
    // restored still carry the pre-release state, and would re-engage what just failed.
    const std::vector<GraspEvent>& events = getRecord(state).events;
    if (!events.empty() && events.back().kind == GraspEventKind::Release && !(state.getTime() > events.back().time)) return;
    if (!(q > 0 && q >= getRecord(state).qThreshold)) return;
    // Not while the grasp carries a load at its compliance limits, nor while it is still taking up
    // its load (findReengageObstacle): handed back because the load reached them, the grasp stays
    // in full contact, which decides the slip. Before the first engagement the limits are this
    // state's: a grasp that has not settled yet (a side still at zero) would be handed back at once.
    std::optional<ComplianceReleaseLimits> limits = getRecord(state).releaseLimits;
    if (!limits && !multi_ && options_.releaseTrigger == ApproxReleaseTrigger::Compliance) {
        const SimTK::Transform& X_GO = context_.object.getBodyTransform(state);
        const double mu = findLimitFriction(context_.contactParameters, options_, true);
        limits = calcComplianceLimits(context_, state, reports, mu, calcFrictionLimits(reports, mu), X_GO.R(), X_GO.p(),
                                      options_.releaseGive.value_or(kDefaultReleaseGive));
    }
    if (limits && !findReengageObstacle(context_, state, reports, *limits).empty()) return;
    engage(state, q, reports, limits);
}

// The engage event's text: the threshold and the limits (one force and one torque for the thesis's
// box, every axis for per-axis limits, both sides of every axis for two-sided ones).
std::string GraspSwitch::describeEngagement(double qThreshold, const grasp::AttachmentEngagement& engagement) const {
    const SimTK::Vec6& limits = engagement.limits;
    if (engagement.lowerLimits) {
        return format("Q >= Q_Th = %.6g N; compliance limits", qThreshold) + describeTwoSided(*engagement.lowerLimits, limits);
    }
    if (options_.limitModel == grasp::FrictionLimitModel::Thesis) {
        return format("Q >= Q_Th = %.6g N; limits %.6g N", qThreshold, limits[3]) + format(", %.6g N m", limits[0]);
    }
    return format("Q >= Q_Th = %.6g N; contact limits %.6g", qThreshold, limits[3]) + format(" %.6g", limits[4]) +
           format(" %.6g N, ", limits[5]) + format("%.6g %.6g", limits[0], limits[1]) + format(" %.6g N m", limits[2]);
}

void GraspSwitch::engage(SimTK::State& state, double quality, const std::vector<contact::ContactReport>& reports,
                         std::optional<ComplianceReleaseLimits> releaseLimits) const {
    updRecord(state).tracker.capture(state, reports);  // penetration, for both attachments; Q tracking is merged's
    const double qThreshold = getRecord(state).qThreshold;
    if (multi_) {
        const std::string limitsText = multi_->engage(state, reports);
        updRecord(state).events.push_back({state.getTime(), GraspEventKind::Engage, quality, format("Q >= Q_Th = %.6g N; ", qThreshold) + limitsText});
        return;
    }
    grasp::AttachmentEngagement engagement;
    const contact::ContactParameters& pair = context_.contactParameters;
    const bool compliance = options_.limitModel == grasp::FrictionLimitModel::Compliance;
    const double mu = findLimitFriction(pair, options_, compliance);
    // M at the contact centroid, where the friction acts; for the compliance limits, which are the
    // model's capacities for loads through M's origin, at the object's centre of mass (O's origin),
    // where the loads an object carries act (its weight and inertia, the capacity protocol's ramp).
    const SimTK::Vec3 p_GM = compliance ? context_.object.getBodyOriginLocation(state) : findContactCentroid(reports);
    placeConstraintFrames(state, p_GM, engagement);
    if (options_.limitModel == grasp::FrictionLimitModel::Thesis) {
        engagement.limits = calcFrictionLimits(reports, mu);
    } else if (compliance) {
        const ComplianceReleaseLimits limits =
            calcComplianceLimits(context_, state, reports, mu, calcFrictionLimits(reports, mu), context_.object.getBodyTransform(state).R(), p_GM,
                                 grasp::ComplianceLimitOptions{}.slipDistance);
        engagement.limits = limits.upper;
        engagement.lowerLimits = limits.lower;
    } else {
        engagement.limits = calcContactGeometryLimits(reports, mu, context_.object.getBodyTransform(state).R(), p_GM);
    }
    engagement.leverArm = findLeverArm(reports, p_GM);
    engagement.penetrationBound = options_.maxEngagedPenetration;
    FollowedGrasp followed;
    if (options_.bushingGive == ApproxBushingGive::Model || options_.bushingGive == ApproxBushingGive::Coupled) {
        const bool coupled = options_.bushingGive == ApproxBushingGive::Coupled;
        followed = captureFollowedGrasp(context_, state, reports, setModelGive(context_, state, reports, p_GM, coupled, engagement));
    }
    for (int k = 0; k < 6; ++k) engagement.lockedAxes[k] = !(*options_.relaxedAxes)[k];
    context_.contacts.setPairsEnabled(state, context_.contacts.findAllPairIndices(), false);  // (b)
    setFingersMerged(state, true);                                                        // (c)
    context_.attachment.engage(state, engagement);                                                // (d)
    const SimTK::Transform X_HO = ~context_.palm.getBodyTransform(state) * context_.object.getBodyTransform(state);
    std::string text = describeEngagement(qThreshold, engagement);
    text += describeModelGive(engagement);
    // As --limits compliance computes them (static friction unless told otherwise, M at O's origin
    // with O's orientation), whatever the constraint's own limits are; at the first engagement
    // only, on the unloaded grasp, and kept for the run.
    if (getRecord(state).releaseLimits) {
        text += "; release at the first engagement's compliance limits";
    } else if (releaseLimits) {
        capAtSlipOnset(*releaseLimits, engagement.lowerLimits.value_or(engagement.limits), engagement.limits,
                       engagement.lockedAxes, context_.attachment.getSlipOnsetFraction());
        text += "; release at compliance limits" + describeTwoSided(releaseLimits->lower, releaseLimits->upper) +
                describeSlipOnsetSides(*releaseLimits);
    }
    GraspSwitchRecord& record = updRecord(state);
    record.X_HO_engaged = X_HO;
    record.releaseLimits = releaseLimits;
    record.followed = std::move(followed);
    record.events.push_back({state.getTime(), GraspEventKind::Engage, quality, text});  // (e)
}

// F on the palm and M on the object coincide at the contact centroid, with O's orientation.
void GraspSwitch::placeConstraintFrames(const SimTK::State& state, const SimTK::Vec3& p_GC,
                                        grasp::AttachmentEngagement& engagement) const {
    const SimTK::Transform& X_GO = context_.object.getBodyTransform(state);
    const SimTK::Transform& X_GH = context_.palm.getBodyTransform(state);
    engagement.X_OM = SimTK::Transform(~X_GO * p_GC);  // O's orientation
    engagement.X_HF = ~X_GH * X_GO * engagement.X_OM;
}

void GraspSwitch::checkRelease(SimTK::State& state) const {
    if (!getRecord(state).followed.pads.empty()) {
        const FollowedGrasp followed = getRecord(state).followed;  // a copy: the move writes the State
        followObjectGive(context_, state, followed, kFollowTolerance);
    }
    double q = 0;
    std::string reason;
    // Written back only when a maximum grew: writing the record (a discrete variable) at every
    // check made the engaged hold cost 1.8 times its floor instead of 1.2 (graspsim bench).
    EngagedGraspTracker tracker = getRecord(state).tracker;
    const double growth = tracker.measurePenetration(state);
    const PenetrationStats& before = getRecord(state).tracker.getPenetration();
    const PenetrationStats& after = tracker.getPenetration();
    if (after.maxWhileEngaged != before.maxWhileEngaged || after.maxGrowth != before.maxGrowth) {
        updRecord(state).tracker = std::move(tracker);
    }
    if (growth > options_.releasePenetration) {
        q = calcEngagedQuality(state);
        reason = format("a fingertip sank %.6g m deeper into the object (limit %.6g m)", growth, options_.releasePenetration);
    } else if (multi_) {
        q = calcEngagedQuality(state);
        std::vector<GraspEvent> events = getRecord(state).events;
        reason = multi_->update(state, q, events);
        updRecord(state).events = std::move(events);
        const double qMinimum = getRecord(state).qMinimum;
        if (reason.empty() && q < qMinimum) reason = format("Q < Q_M = %.6g N", qMinimum);
    } else {
        q = calcEngagedQuality(state);
        reason = describeRelease(state, q);
    }
    if (!reason.empty()) release(state, q, reason);
}

// Empty while the approximation still holds; otherwise the first reason to release, with numbers.
std::string GraspSwitch::describeRelease(const SimTK::State& state, double quality) const {
    context_.model.getSystem().realize(state, SimTK::Stage::Position);
    const SimTK::Transform X_HO = ~context_.palm.getBodyTransform(state) * context_.object.getBodyTransform(state);
    const GraspSwitchRecord& record = getRecord(state);
    const double slide = (X_HO.p() - record.X_HO_engaged.p()).norm();
    if (slide > options_.releaseSlideDistance) {
        return format("object slid %.6g m in the hand (limit %.6g m)", slide, options_.releaseSlideDistance);
    }
    const double distance = context_.goals.findMaxDistance(state);
    const double tolerance = context_.heldTolerance;
    if (distance > tolerance) return format("fingertip %.6g m from its goal (held tolerance %.6g m)", distance, tolerance);
    if (record.releaseLimits) {
        std::string atLimit = describeComplianceRelease(state, *record.releaseLimits);
        if (!atLimit.empty()) return atLimit;
    }
    if (quality < record.qMinimum) return format("Q < Q_M = %.6g N", record.qMinimum);
    return {};
}

// The first axis side on which the constraint's reaction on the object (about O's origin, in O:
// the frame of the limits), or else the carried load, has reached the compliance model's limit;
// empty if neither has.
std::string GraspSwitch::describeComplianceRelease(const SimTK::State& state, const ComplianceReleaseLimits& limits) const {
    context_.model.getSystem().realize(state, context_.attachment.getReactionStage());
    const std::string reason = findComplianceLimitReached(findReactionInO(state), limits);
    const std::optional<SimTK::Vec6> load = findCarriedLoadInO(state);
    if (!reason.empty() || !load) return reason;
    return findComplianceLimitReached(*load, limits, "carried load (gravity and external loads)");
}

SimTK::Vec6 GraspSwitch::findReactionInO(const SimTK::State& state) const {
    const SimTK::SpatialVec wrench_G = context_.attachment.findReactionOnObject(state);
    const SimTK::Rotation R_OG = ~context_.object.getBodyTransform(state).R();
    const SimTK::Vec3 moment_O = R_OG * wrench_G[0], force_O = R_OG * wrench_G[1];
    SimTK::Vec6 reaction;
    for (int k = 0; k < 3; ++k) reaction[k] = moment_O[k], reaction[k + 3] = force_O[k];
    return reaction;
}

// What the constraint would carry with the object at rest, as its reaction is expressed: the
// moment about O's origin, the centre of mass, where gravity and the loads' forces act. None while
// no external load acts: the reaction carries gravity itself, the switch engages only inside the
// limits, and the direction model's margin is the witness's dearest part (graspsim bench's hold).
std::optional<SimTK::Vec6> GraspSwitch::findCarriedLoadInO(const SimTK::State& state) const {
    if (!loads_) return std::nullopt;
    const SimTK::SpatialVec external_G = loads_->findWrenchAt(state.getTime());
    if (external_G[0] == SimTK::Vec3(0) && external_G[1] == SimTK::Vec3(0)) return std::nullopt;
    const SimTK::Vec3 weight_G = context_.object.getBodyMass(state) * context_.model.getGravity().getGravityVector(state);
    const SimTK::Rotation R_OG = ~context_.object.getBodyTransform(state).R();
    const SimTK::Vec3 moment_O = -(R_OG * external_G[0]), force_O = -(R_OG * (external_G[1] + weight_G));
    SimTK::Vec6 carried;
    for (int k = 0; k < 3; ++k) carried[k] = moment_O[k], carried[k + 3] = force_O[k];
    return carried;
}

// A deflected hand-back only where the compliance limits are what was reached (by the reaction or
// else the carried load, deflected by whichever reached them): at the other rules' releases the
// constraint may have slid, and its reaction is not the load the model meant.
void GraspSwitch::release(SimTK::State& state, double quality, const std::string& reason) const {
    const SimTK::MultibodySystem& system = context_.model.getSystem();
    system.realize(state, SimTK::Stage::Velocity);
    const SimTK::Vec3 v_before = context_.object.getBodyOriginVelocity(state);
    const std::optional<ComplianceReleaseLimits>& limits = getRecord(state).releaseLimits;
    std::optional<HandBackDeflection> deflection;
    if (options_.handBack == ApproxHandBack::Deflected && limits) {
        SimTK::Vec6 load = findReactionInO(state);
        const std::optional<SimTK::Vec6> carried = findCarriedLoadInO(state);
        if (carried && findComplianceLimitReached(load, *limits).empty()) load = *carried;
        if (!findComplianceLimitReached(load, *limits).empty()) deflection = calcHandBackDeflection(context_, state, *limits, load);
    }
    context_.attachment.release(state);
    if (!multi_) setFingersMerged(state, false);  // multi never merges them
    context_.contacts.setPairsEnabled(state, context_.contacts.findAllPairIndices(), true);
    if (deflection) applyHandBackDeflection(context_, state, getRecord(state).X_HO_engaged, *deflection);
    const double velocityJump = findVelocityJump(state, v_before);
    const std::string text = deflection ? reason + describeHandBackDeflection(*deflection) : reason;
    updRecord(state).events.push_back({state.getTime(), GraspEventKind::Release, quality, text, velocityJump});
}

// The object's velocity as the integrator will restart from it: realized after the switch and
// projected onto whatever constraints remain, as the TimeStepper's reinitialization does.
double GraspSwitch::findVelocityJump(SimTK::State& state, const SimTK::Vec3& v_before) const {
    const SimTK::MultibodySystem& system = context_.model.getSystem();
    system.realize(state, SimTK::Stage::Velocity);
    system.projectU(state, 1e-12);
    system.realize(state, SimTK::Stage::Velocity);
    return (context_.object.getBodyOriginVelocity(state) - v_before).norm();
}

// Locking at Motion::Position keeps each finger joint at its current angle (and zero rate
// relative to its parent): the fingers become part of one rigid body with the palm.
void GraspSwitch::setFingersMerged(SimTK::State& state, bool merged) const {
    const SimTK::SimbodyMatterSubsystem& matter = context_.model.getMatter();
    for (SimTK::MobilizedBodyIndex index : context_.fingerMobilizers) {
        const SimTK::MobilizedBody& mobod = matter.getMobilizedBody(index);
        if (merged) {
            mobod.lock(state, SimTK::Motion::Position);
        } else {
            mobod.unlock(state);
        }
    }
}

}  // namespace graspsim::simulation
