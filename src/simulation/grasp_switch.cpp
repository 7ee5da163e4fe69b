#include "graspsim/simulation/grasp_switch.h"

#include "graspsim/error.h"
#include "graspsim/grasp/limited_bushing_law.h"
#include "graspsim/simulation/contact_grasp_quality.h"
#include "graspsim/simulation/grasp_scene.h"
#include "graspsim/simulation/multi_attachment_switch.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace graspsim::simulation {

namespace {

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
        g.p_GC = Eigen::Vector3d(c.p_G[0], c.p_G[1], c.p_G[2]);
        g.n_G = Eigen::Vector3d(c.n_G[0], c.n_G[1], c.n_G[2]);
        g.normalForce = c.normalForce;
        contacts.push_back(g);
    }
    Eigen::Matrix3d R;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) R(i, j) = R_GM.asMat33()(i, j);
    const Eigen::Matrix<double, 6, 1> limits =
        grasp::calcContactGeometryLimits(contacts, mu, R, Eigen::Vector3d(p_GM[0], p_GM[1], p_GM[2]));
    SimTK::Vec6 result;
    for (int k = 0; k < 6; ++k) result[k] = limits[k];
    return result;
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

// The run's options over the scenario's approximation section: a value given to the run wins.
ApproxOptions resolveOptions(const ApproxOptions& given, const scenario::ApproximationSpec& scenario) {
    ApproxOptions options = given;
    if (options.qThreshold == 0) options.qThreshold = scenario.qThreshold;
    if (options.qMinimum == 0) options.qMinimum = scenario.qMinimum;
    if (!options.relaxedAxes) options.relaxedAxes = scenario.relaxedAxes;
    return options;
}

const grasp::GraspAttachment& findAttachment(const GraspScene& scene) {
    if (!scene.getAttachment()) throw Error("grasp switch: the scene has no attachment (not an approx-mode scene)");
    return *scene.getAttachment();
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

GraspSwitch::GraspSwitch(const GraspScene& scene, SimTK::GeneralForceSubsystem& forces,
                         const control::GraspController& controller, const ApproxOptions& options, double interval)
    : SimTK::PeriodicEventHandler(interval), scene_(scene), controller_(controller),
      attachment_(findAttachment(scene)), options_(resolveOptions(options, scene.getScenario().approximation)) {
    if (!(options_.qThreshold >= 0) || !(options_.qMinimum >= 0)) {
        throw InputError("approx: the quality thresholds Q_Th and Q_M must be >= 0 (0 = automatic)");
    }
    if (!(options_.releaseSlideDistance > 0)) throw InputError("approx: the release slide distance must be > 0 m");
    if (!(options_.maxEngagedPenetration > 0)) throw InputError("approx: the engaged penetration bound must be > 0 m");
    if (options_.qThreshold > 0 && options_.qMinimum >= options_.qThreshold) {
        throw InputError(format("approx: Q_M (%g N) must be below Q_Th (%g N)", options_.qMinimum, options_.qThreshold));
    }
    GraspSwitchRecord initial{options_.qThreshold, 0, SimTK::Transform(), {}, EngagedGraspTracker(scene)};
    initial.qMinimum = options_.qMinimum > 0 ? options_.qMinimum : options_.hysteresisFraction * initial.qThreshold;
    auto* keeper = new RecordKeeper(forces, std::move(initial));
    SimTK::Force::Custom(forces, keeper);
    keeper_ = keeper;
    const model::ModelDescription& d = scene.getModel().getDescription();
    for (const std::string& e : scene.getGoalEndEffectors()) goalBodies_.push_back(d.findEndEffector(e)->body);
    if (scene.getMultiAttachment()) multi_ = std::make_unique<MultiAttachmentSwitch>(scene, options.releaseSlideDistance, options.maxEngagedPenetration);
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

bool GraspSwitch::isEngaged(const SimTK::State& state) const { return attachment_.isEngaged(state); }

void GraspSwitch::handleEvent(SimTK::State& state, SimTK::Real accuracy, bool& shouldTerminate) const {
    shouldTerminate = false;
    if (isEngaged(state)) {
        checkRelease(state);  // IK paused: the fingers are locked to the palm
        return;
    }
    controller_.handleEvent(state, accuracy, shouldTerminate);
    if (!scene_.isObjectHeld(state)) checkEngage(state);  // only once the object is released
}

double GraspSwitch::calcQuality(const SimTK::State& state) const {
    scene_.getSystem().realize(state, SimTK::Stage::Velocity);
    return calcQualityOf(state, scene_.getCompliantContacts().findContactReports(state));
}

double GraspSwitch::calcQualityOf(const SimTK::State& state, const std::vector<contact::ContactReport>& reports) const {
    return calcContactGraspQuality(reports, scene_.getObject().getBodyTransform(state),
                                   makeQualityOptions(scene_.getContactParameters()));
}

double GraspSwitch::calcEngagedQuality(const SimTK::State& state) const {
    if (const double* known = keeper_->findEngagedQuality(state)) return *known;
    double q = 0;
    if (!multi_) {
        q = getRecord(state).tracker.calcQuality(state);
    } else {
        // Multi: the fingers move on their own and the palm-fixed tracker does not apply; Q is that
        // of the contacts every pair would produce in `state`, switched on or not.
        scene_.getSystem().realize(state, SimTK::Stage::Velocity);
        q = calcQualityOf(state, scene_.getCompliantContacts().findContactReports(state, scene_.getCompliantContacts().findAllPairIndices()));
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
    const double limit = scene_.getContactParameters().transitionVelocity;
    return std::all_of(reports.begin(), reports.end(),
                       [&](const contact::ContactReport& c) { return c.slipVelocity_G.norm() < limit; });
}

// One set of contact reports serves every test of the check and the engagement itself.
void GraspSwitch::checkEngage(SimTK::State& state) const {
    scene_.getSystem().realize(state, SimTK::Stage::Velocity);
    const std::vector<contact::ContactReport> reports = scene_.getCompliantContacts().findContactReports(state);
    if (!isFullContact(reports)) return;
    const double q = calcQualityOf(state, reports);
    if (getRecord(state).qThreshold == 0) {
        // Automatic Q_Th from the first full-contact check once the grasp has settled.
        if (state.getTime() < scene_.getScenario().simulation.settleTime - 1e-12) return;
        GraspSwitchRecord& record = updRecord(state);
        record.qThreshold = options_.autoThresholdFraction * q;
        if (options_.qMinimum == 0) record.qMinimum = options_.hysteresisFraction * record.qThreshold;
    }
    if (!isSticking(reports)) return;
    // Not at the instant of a release (a witness may release at a check's time): the contacts just
    // restored still carry the pre-release state, and would re-engage what just failed.
    const std::vector<GraspEvent>& events = getRecord(state).events;
    if (!events.empty() && events.back().kind == GraspEventKind::Release && !(state.getTime() > events.back().time)) return;
    if (q > 0 && q >= getRecord(state).qThreshold) engage(state, q, reports);
}

// The engage event's text: the threshold and the limits (one force and one torque for the thesis's
// box, every axis for per-axis limits).
std::string GraspSwitch::describeEngagement(double qThreshold, const SimTK::Vec6& limits) const {
    if (options_.limitModel == grasp::FrictionLimitModel::Thesis) {
        return format("Q >= Q_Th = %.6g N; limits %.6g N", qThreshold, limits[3]) + format(", %.6g N m", limits[0]);
    }
    return format("Q >= Q_Th = %.6g N; contact limits %.6g", qThreshold, limits[3]) + format(" %.6g", limits[4]) +
           format(" %.6g N, ", limits[5]) + format("%.6g %.6g", limits[0], limits[1]) + format(" %.6g N m", limits[2]);
}

void GraspSwitch::engage(SimTK::State& state, double quality, const std::vector<contact::ContactReport>& reports) const {
    updRecord(state).tracker.capture(state, reports);  // penetration, for both attachments; Q tracking is merged's
    const double qThreshold = getRecord(state).qThreshold;
    if (multi_) {
        const std::string limitsText = multi_->engage(state, reports);
        updRecord(state).events.push_back({state.getTime(), GraspEventKind::Engage, quality, format("Q >= Q_Th = %.6g N; ", qThreshold) + limitsText});
        return;
    }
    grasp::AttachmentEngagement engagement;
    const contact::ContactParameters& pair = scene_.getContactParameters();
    const double mu = options_.staticFrictionLimits ? pair.staticFriction : pair.dynamicFriction;
    const SimTK::Vec3 p_GC = findContactCentroid(reports);
    placeConstraintFrames(state, p_GC, engagement);
    if (options_.limitModel == grasp::FrictionLimitModel::Thesis) {
        engagement.limits = calcFrictionLimits(reports, mu);
    } else {
        engagement.limits = calcContactGeometryLimits(reports, mu, scene_.getObject().getBodyTransform(state).R(), p_GC);
    }
    engagement.leverArm = findLeverArm(reports, p_GC);
    engagement.penetrationBound = options_.maxEngagedPenetration;
    for (int k = 0; k < 6; ++k) engagement.lockedAxes[k] = !(*options_.relaxedAxes)[k];
    scene_.getCompliantContacts().setPairsEnabled(state, scene_.getCompliantContacts().findAllPairIndices(), false);  // (b)
    setFingersMerged(state, true);                                                        // (c)
    attachment_.engage(state, engagement);                                                // (d)
    const SimTK::Transform X_HO = ~scene_.getPalm().getBodyTransform(state) * scene_.getObject().getBodyTransform(state);
    GraspSwitchRecord& record = updRecord(state);
    record.X_HO_engaged = X_HO;
    record.events.push_back({state.getTime(), GraspEventKind::Engage, quality, describeEngagement(qThreshold, engagement.limits)});  // (e)
}

// F on the palm and M on the object coincide at the contact centroid, with O's orientation.
void GraspSwitch::placeConstraintFrames(const SimTK::State& state, const SimTK::Vec3& p_GC,
                                        grasp::AttachmentEngagement& engagement) const {
    const SimTK::Transform& X_GO = scene_.getObject().getBodyTransform(state);
    const SimTK::Transform& X_GH = scene_.getPalm().getBodyTransform(state);
    engagement.X_OM = SimTK::Transform(~X_GO * p_GC);  // O's orientation
    engagement.X_HF = ~X_GH * X_GO * engagement.X_OM;
}

void GraspSwitch::checkRelease(SimTK::State& state) const {
    double q = 0;
    std::string reason;
    // Written back only when a maximum grew: writing the record (a discrete variable) at every
    // check made the engaged hold cost 1.8 times its floor instead of 1.2 (graspsim bench).
    EngagedGraspTracker tracker = getRecord(state).tracker;
    tracker.measurePenetration(state);
    const PenetrationStats& before = getRecord(state).tracker.getPenetration();
    const PenetrationStats& after = tracker.getPenetration();
    if (after.maxWhileEngaged != before.maxWhileEngaged || after.maxGrowth != before.maxGrowth) {
        updRecord(state).tracker = std::move(tracker);
    }
    if (multi_) {
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
    scene_.getSystem().realize(state, SimTK::Stage::Position);
    const SimTK::Transform X_HO = ~scene_.getPalm().getBodyTransform(state) * scene_.getObject().getBodyTransform(state);
    const GraspSwitchRecord& record = getRecord(state);
    const double slide = (X_HO.p() - record.X_HO_engaged.p()).norm();
    if (slide > options_.releaseSlideDistance) {
        return format("object slid %.6g m in the hand (limit %.6g m)", slide, options_.releaseSlideDistance);
    }
    const double distance = scene_.findMaxFingertipGoalDistance(state);
    const double tolerance = scene_.getScenario().simulation.heldTolerance;
    if (distance > tolerance) return format("fingertip %.6g m from its goal (held tolerance %.6g m)", distance, tolerance);
    if (quality < record.qMinimum) return format("Q < Q_M = %.6g N", record.qMinimum);
    return {};
}

void GraspSwitch::release(SimTK::State& state, double quality, const std::string& reason) const {
    const SimTK::MultibodySystem& system = scene_.getSystem();
    system.realize(state, SimTK::Stage::Velocity);
    const SimTK::Vec3 v_before = scene_.getObject().getBodyOriginVelocity(state);
    attachment_.release(state);
    if (!multi_) setFingersMerged(state, false);  // multi never merges them
    scene_.getCompliantContacts().setPairsEnabled(state, scene_.getCompliantContacts().findAllPairIndices(), true);
    const double velocityJump = findVelocityJump(state, v_before);
    updRecord(state).events.push_back({state.getTime(), GraspEventKind::Release, quality, reason, velocityJump});
}

// The object's velocity as the integrator will restart from it: realized after the switch and
// projected onto whatever constraints remain, as the TimeStepper's reinitialization does.
double GraspSwitch::findVelocityJump(SimTK::State& state, const SimTK::Vec3& v_before) const {
    const SimTK::MultibodySystem& system = scene_.getSystem();
    system.realize(state, SimTK::Stage::Velocity);
    system.projectU(state, 1e-12);
    system.realize(state, SimTK::Stage::Velocity);
    return (scene_.getObject().getBodyOriginVelocity(state) - v_before).norm();
}

// Locking at Motion::Position keeps each finger joint at its current angle (and zero rate
// relative to its parent): the fingers become part of one rigid body with the palm.
void GraspSwitch::setFingersMerged(SimTK::State& state, bool merged) const {
    const SimTK::SimbodyMatterSubsystem& matter = scene_.getModel().getMatter();
    for (SimTK::MobilizedBodyIndex index : scene_.getFingerMobilizers()) {
        const SimTK::MobilizedBody& mobod = matter.getMobilizedBody(index);
        if (merged) {
            mobod.lock(state, SimTK::Motion::Position);
        } else {
            mobod.unlock(state);
        }
    }
}

}  // namespace graspsim::simulation
