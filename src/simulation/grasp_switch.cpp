#include "graspsim/simulation/grasp_switch.h"

#include "graspsim/error.h"
#include "graspsim/simulation/compliance_release.h"
#include "graspsim/simulation/contact_grasp_quality.h"
#include "graspsim/simulation/creep_release.h"
#include "graspsim/simulation/deflected_hand_back.h"
#include "graspsim/simulation/multi_attachment_switch.h"

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

}  // namespace

std::string GraspSwitch::formatText(const char* pattern, double a, double b) {
    char buffer[160];
    std::snprintf(buffer, sizeof buffer, pattern, a, b);
    return buffer;
}

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
        creepIndex_ = forces_.allocateDiscreteVariable(state, SimTK::Stage::Report, new SimTK::Value<CreepWatch>(CreepWatch{}));
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
    // The creep watch apart from the record: written at every check under a load, and small.
    const CreepWatch& getCreepWatch(const SimTK::State& state) const {
        return SimTK::Value<CreepWatch>::downcast(forces_.getDiscreteVariable(state, creepIndex_)).get();
    }
    CreepWatch& updCreepWatch(SimTK::State& state) const {
        return SimTK::Value<CreepWatch>::updDowncast(forces_.updDiscreteVariable(state, creepIndex_)).upd();
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
    mutable SimTK::DiscreteVariableIndex creepIndex_;
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
const CreepWatch& GraspSwitch::getCreepWatch(const SimTK::State& state) const { return keeper_->getCreepWatch(state); }
CreepWatch& GraspSwitch::updCreepWatch(SimTK::State& state) const { return keeper_->updCreepWatch(state); }

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
        reason = formatText("a fingertip sank %.6g m deeper into the object (limit %.6g m)", growth, options_.releasePenetration);
    } else if (multi_) {
        q = calcEngagedQuality(state);
        std::vector<GraspEvent> events = getRecord(state).events;
        reason = multi_->update(state, q, events);
        updRecord(state).events = std::move(events);
        const double qMinimum = getRecord(state).qMinimum;
        if (reason.empty() && q < qMinimum) reason = formatText("Q < Q_M = %.6g N", qMinimum);
    } else {
        q = calcEngagedQuality(state);
        if (getCreepWatch(state).model) {
            const auto beyond = findCarriedLoadBeyondEngagement(state, *getRecord(state).releaseLimits);
            updateCreepWatch(updCreepWatch(state), beyond, state.getTime());
        }
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
        return formatText("object slid %.6g m in the hand (limit %.6g m)", slide, options_.releaseSlideDistance);
    }
    const double distance = context_.goals.findMaxDistance(state);
    const double tolerance = context_.heldTolerance;
    if (distance > tolerance) return formatText("fingertip %.6g m from its goal (held tolerance %.6g m)", distance, tolerance);
    if (record.releaseLimits) {
        std::string atLimit = describeComplianceRelease(state, *record.releaseLimits);
        if (!atLimit.empty()) return atLimit;
        atLimit = describeCreepRelease(getCreepWatch(state), options_.releaseGive.value_or(kDefaultReleaseGive));
        if (!atLimit.empty()) return atLimit;
    }
    if (quality < record.qMinimum) return formatText("Q < Q_M = %.6g N", record.qMinimum);
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

// The carried load less what the contacts carried at engagement, as the creep watch takes it; none
// while no external load acts (findCarriedLoadInO).
std::optional<Eigen::Matrix<double, 6, 1>> GraspSwitch::findCarriedLoadBeyondEngagement(const SimTK::State& state,
                                                                                       const ComplianceReleaseLimits& limits) const {
    const std::optional<SimTK::Vec6> carried = findCarriedLoadInO(state);
    if (!carried) return std::nullopt;
    return findLoadBeyondEngagement(*carried, limits);
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
