#pragma once
/// @file
/// The grasp switch of `--mode approx` (thesis Figure 4.1, section 4.2): a Simbody periodic
/// event handler that replaces the finger-object contacts by one friction-limited 6-DOF element
/// once the grasp is firm, and gives them back when the approximation stops being believable.
///
/// Every `ik_interval` (the IK's own period, so the check costs no extra event):
///  - UNGRASPED (constraint disabled): run the grasp controller's IK update, then, once the object
///    has been released, compute the grasp quality Q from the contact reports exactly as the
///    recorder does (calcContactGraspQuality, static friction). In full contact (every goal
///    fingertip touching the object), with every hand-object contact sticking (slip slower than
///    the scenario's transition velocity, i.e. inside its friction cone; an object already
///    sliding out of the hand is not grasped firmly) and Q >= Q_Th, ENGAGE:
///     (a) limits from the contacts (eq. 4.1-4.3): F_perp = sum f_i . n_i, r = mean distance of
///         the contact points to their centroid; translation limits mu F_perp, rotation limits
///         mu r F_perp, with mu the scenario's DYNAMIC friction: the limit is reached only when
///         the object slides, and sliding skin-on-object friction is the dynamic one (below
///         the limit the bushing sticks elastically and the weld rigidly, which is what static friction gives);
///         or per axis from the contacts' geometry (ApproxOptions::limitModel contact), or two-sided
///         per axis from the grasp's compliance model (compliance: grasp/compliance_limits.h, with
///         the fingers' compliance of finger_compliance.h at this state and mu_s by default);
///     (b) disable every hand-object contact pair;
///     (c) MERGE: lock every finger joint's mobilizer at its current angle, so hand and fingers
///         move as one composite body. Realism lost: the fingers no longer flex while engaged
///         (the thesis notes the same loss of dexterity), and their PD torques do nothing;
///     (d) enable the palm (H) - object (O) constraint of ApproxOptions::constraint at the current
///         pose, limits set, axes relaxed or locked per ApproxOptions::relaxedAxes: the bushing
///         with its anchor reset there (no force jump) and its stiffness raised from the limits
///         so that its elastic deflection at them moves no fingertip deeper than
///         ApproxOptions::maxEngagedPenetration (K_t = 2 sqrt(3) L_t / bound, K_r = 2 sqrt(3) r L_r
///         / bound, r the farthest contact from the centroid, never below the default stiffness of kBushingFrequency;
///         critically damped), or the weld (every axis stuck, those already over their limit
///         sliding). Its frames F (on the palm) and M (on the object)
///         are placed, coincident, at the CENTROID OF THE CONTACT POINTS at this instant, with
///         the object's orientation; the axes are those of O. DELIBERATE DEPARTURE from the
///         thesis (section 4.2 puts the constraint at the object's centre of mass): friction acts
///         at the contacts, and the rotation limit mu r F_perp (r measured from the contact
///         centroid, eq. 4.2) is a limit on the moment about the contact centroid. At the centre
///         of mass a force through the centre of mass makes no moment on the constraint, so a
///         pull that levers the object out of a pinch (phone-pinch f1: 2 N at 2.6 cm from the
///         pinch) was held by the approximation while full contact drops the object; at the
///         centroid the same pull makes its real moment about the grip, and the verdicts agree.
///         The compliance limits are the exception: they are the model's capacities for loads
///         through M's origin, which the model already shares among the contacts by their
///         positions (a load's moment about the grip included), so M is at the centre of mass,
///         where weight, inertia and the capacity protocol's loads act;
///     (e) record an "engage" event.
///  With ApproxOptions::attach Multi, (c) and (d) are replaced by multi_attachment_switch.h (fingers
///  stay free, one friction-limited part per fingertip, fingers detached one by one).
///  - GRASPED (constraint enabled): IK is skipped (the fingers are locked, and skipping it is where
///    the approximation saves its time). The contacts are still tracked without entering the
///    dynamics (engaged_grasp_tracker.h): their penetration is measured as if the pairs were on
///    (nothing applied, the state untouched), and Q is estimated from the constraint's reaction wrench
///    distributed over the contacts captured at engagement. RELEASE (constraint off, fingers
///    unlocked, contacts on, "release" event) when a replaced contact's depth has grown more than
///    releasePenetration beyond its depth at engagement (the constraint sliding the object into a
///    locked finger), when the object's centre of mass has moved more
///    than releaseSlideDistance relative to the palm since engagement, when a fingertip is
///    farther than the scenario's held tolerance from its goal on the object, or when that Q <
///    Q_M; and with ApproxOptions::releaseTrigger Compliance (`--release-at compliance`), when the
///    constraint's reaction on the object (about O's origin, along O's axes) reaches, on any axis
///    side, the two-sided limit of the grasp's compliance model computed at engagement as for the
///    compliance limits (with the thesis's box still the constraint's own limits, nothing slides
///    before that; full contact, restored from the same state, then decides whether the object
///    slips). The limits are those of the first engagement, kept for the run, and the switch does
///    not engage again while the wrench it would hold is outside them, nor while the object still
///    moves in the palm faster than the contacts' transition velocity: compliance_release.h,
///    findReengageObstacle). Nothing at the release changes a velocity (the constraint and the locks are switched
///    off, contact comes back as a force), so the object's velocity is continuous; the event
///    records the measured jump (GraspEvent::velocityJump) to show it.
///
/// Q_Th: ApproxOptions::qThreshold, or automatically autoThresholdFraction times the quality of
/// the first full-contact check at or after the scenario's settle_time (the thesis sets Q_Th by
/// hand as the quality at which the object rests under gravity without slipping; the settled
/// full-contact grasp is that state). Q_M: qMinimum, or hysteresisFraction * Q_Th.
///
/// Every switch changes Instance-stage variables (pair flags, locks, constraint flags); doing it in
/// an event handler makes the TimeStepper re-realize and reinitialize the integrator.
/// What the switch has decided (the thresholds in use, the engagement pose, the event log, the
/// tracked contacts) is a GraspSwitchRecord kept in the State, in a Report-stage discrete
/// variable: writing it changes no dynamics, so it restarts no integrator, and a copied State
/// carries its own history.

#include "graspsim/simulation/approximation_context.h"
#include "graspsim/simulation/compliance_release.h"
#include "graspsim/simulation/creep_release.h"
#include "graspsim/simulation/engaged_grasp_tracker.h"
#include "graspsim/simulation/finger_follow.h"
#include "graspsim/simulation/object_loads.h"
#include "graspsim/simulation/simulation_options.h"

#include "graspsim/simbody.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace graspsim::simulation {

class MultiAttachmentSwitch;

/// What a switch of the approximation did.
enum class GraspEventKind {
    Engage,   ///< the attachment took over from the contacts
    Release,  ///< the contacts took over again
    Detach    ///< multi only: one finger went back to contact, the others still hold
};

/// The word for `kind` in events.csv: "engage", "release" or "detach".
std::string toString(GraspEventKind kind);

/// One switch of the approximation.
struct GraspEvent {
    double time = 0;       ///< s
    GraspEventKind kind = GraspEventKind::Engage;
    double quality = 0;  ///< grasp quality Q at the switch (N; when releasing, the engaged estimate)
    std::string reason;  ///< why, with the numbers
    /// Release only: |v_after - v_before| of the object's centre of mass across the switch (m/s),
    /// "after" being the state the integrator restarts from (realized and projected).
    double velocityJump = 0;
};

/// The switch's decisions so far, part of the State (see the file comment).
struct GraspSwitchRecord {
    double qThreshold = 0;           ///< Q_Th in use (N); 0 until the automatic threshold is set
    double qMinimum = 0;             ///< Q_M in use (N)
    SimTK::Transform X_HO_engaged;   ///< object frame O in the palm frame H at the last engagement (m)
    std::vector<GraspEvent> events;  ///< the switches so far, in time order
    EngagedGraspTracker tracker;     ///< the contacts tracked while engaged, the penetration so far
    /// With ApproxReleaseTrigger::Compliance, the limits computed at the first engagement (on the
    /// unloaded grasp, kept for the run) at which the switch releases, and outside which it does not
    /// engage again; unset otherwise.
    std::optional<ComplianceReleaseLimits> releaseLimits;
    /// With the bushing's rotational give, the pads whose locked fingers follow the object's give
    /// (finger_follow.h); empty otherwise.
    FollowedGrasp followed;
};

/// The periodic event handler described in the file comment (owned by the System once added).
class GraspSwitch : public SimTK::PeriodicEventHandler {
public:
    /// Built by GraspApproximation (grasp_approximation.h), which adds it to the System.
    /// @param context what the switch uses of the scene: its contacts, attachment, finger
    ///        mobilizers and the IK controller it runs while ungrasped (not itself added to the
    ///        System, so IK can be paused); must outlive the switch.
    /// @param forces where the switch keeps its GraspSwitchRecord (an element that applies no force).
    /// @param options resolved (resolveApproxOptions).
    GraspSwitch(const ApproximationContext& context, SimTK::GeneralForceSubsystem& forces, const ApproxOptions& options);
    ~GraspSwitch() override;

    void handleEvent(SimTK::State& state, SimTK::Real accuracy, bool& shouldTerminate) const override;
    /// With ApproxOptions::attach Multi, a new triggered event handler that runs the engaged check
    /// (detaching fingers, maybe releasing) where an attached finger's pressing force falls through
    /// zero, localized by the integrator; nullptr otherwise. Add it to the System beside this
    /// handler, which must outlive it. (Only this cheap condition is a witness: a witness is
    /// evaluated at every dynamics evaluation, and Q there would cost more than the checks save.)
    SimTK::TriggeredEventHandler* makeDetachWitness() const;
    /// With ApproxOptions::releaseTrigger Compliance (merged), a new triggered event handler that
    /// runs the engaged check where the constraint's reaction passes a compliance limit, an axis
    /// side or the model's onset along the load's own direction (findLimitMargin falling through
    /// zero), found by the integrator's event
    /// detection at the end of the step that crosses it, so that the release does not wait for the
    /// next periodic check (up to ik_interval, 10 ms: as long as full contact's slip onset under a
    /// constant load above capacity); nullptr otherwise. Added as makeDetachWitness()'s.
    SimTK::TriggeredEventHandler* makeReleaseWitness() const;

    /// Whether the approximation is engaged in `state`.
    bool isEngaged(const SimTK::State& state) const;
    /// Why the switch's check would not engage in `state`, in words naming the test and its numbers
    /// (a goal segment without contact, before the settle time, a contact slipping at or above the
    /// transition velocity, Q below Q_Th, the held load at the compliance limits); empty when it
    /// would engage, or is engaged. Realizes `state` to Stage::Acceleration.
    std::string findEngageObstacle(const SimTK::State& state) const;
    /// The switch's decisions up to `state`.
    const GraspSwitchRecord& getRecord(const SimTK::State& state) const;
    /// The switches up to `state`, in time order.
    const std::vector<GraspEvent>& getEvents(const SimTK::State& state) const { return getRecord(state).events; }
    /// Q_Th in use (N); 0 until the automatic threshold has been set.
    double getQualityThreshold(const SimTK::State& state) const { return getRecord(state).qThreshold; }
    /// Q_M in use (N).
    double getQualityMinimum(const SimTK::State& state) const { return getRecord(state).qMinimum; }

    /// Grasp quality of the contacts active in `state` (N). Needs Stage::Velocity.
    double calcQuality(const SimTK::State& state) const;
    /// Q while engaged (N). Merged: the constraint's wrench distributed over the tracked contacts
    /// (EngagedGraspTracker::calcQuality; realizes `state` to Stage::Acceleration). Multi: the
    /// quality of the contacts every pair would produce in `state`, switched on or not
    /// (CompliantContactForce::findContactReports of a list), since the fingers move on their own.
    /// Kept in a cache entry of `state` (valid until its time, q, u or switch flags change), so
    /// that the switch's check and the sample recorded at that instant compute it once.
    double calcEngagedQuality(const SimTK::State& state) const;
    /// The contacts tracked while engaged and the penetration measured up to `state`.
    const EngagedGraspTracker& getTracker(const SimTK::State& state) const { return getRecord(state).tracker; }
    /// The run's external loads on the object (they are added after the switch). With them, the
    /// compliance trigger also releases once the load the grasp carries, gravity and `loads` on the
    /// object at rest, reaches the compliance limits: the reaction of a bushing that gives lags that
    /// load under a step (docs/capacity.md, "The carried load"). Set before the topology is realized;
    /// `loads` must outlive the switch.
    void setObjectLoads(const ObjectLoads& loads) { loads_ = &loads; }

private:
    class DetachWitness;
    class ReleaseWitness;
    class RecordKeeper;
    GraspSwitchRecord& updRecord(SimTK::State& state) const;
    const CreepWatch& getCreepWatch(const SimTK::State& state) const;
    CreepWatch& updCreepWatch(SimTK::State& state) const;
    static std::string formatText(const char* pattern, double a, double b = 0);  // snprintf of one or two numbers
    void checkEngage(SimTK::State& state) const;
    void checkRelease(SimTK::State& state) const;
    std::string findGoalWithoutContact(const std::vector<contact::ContactReport>& reports) const;
    const contact::ContactReport* findSlidingContact(const std::vector<contact::ContactReport>& reports) const;
    std::string findEngageObstacle(const SimTK::State& state, const std::vector<contact::ContactReport>& reports, double q,
                                   double qThreshold, std::optional<ComplianceReleaseLimits>& limits) const;
    double calcQualityOf(const SimTK::State& state, const std::vector<contact::ContactReport>& reports) const;
    void engage(SimTK::State& state, double quality, const std::vector<contact::ContactReport>& reports,
                std::optional<ComplianceReleaseLimits> releaseLimits) const;
    void placeConstraintFrames(const SimTK::State& state, const SimTK::Vec3& p_GC,
                               grasp::AttachmentEngagement& engagement) const;
    void release(SimTK::State& state, double quality, const std::string& reason) const;
    void setFingersMerged(SimTK::State& state, bool merged) const;
    std::string describeRelease(const SimTK::State& state, double quality) const;
    std::string describeComplianceRelease(const SimTK::State& state, const ComplianceReleaseLimits& limits) const;
    SimTK::Vec6 findReactionInO(const SimTK::State& state) const;
    std::optional<SimTK::Vec6> findCarriedLoadInO(const SimTK::State& state) const;
    std::optional<Eigen::Matrix<double, 6, 1>> findCarriedLoadBeyondEngagement(const SimTK::State& state,
                                                                             const ComplianceReleaseLimits& limits) const;
    std::string describeEngagement(double qThreshold, const grasp::AttachmentEngagement& engagement) const;
    double findVelocityJump(SimTK::State& state, const SimTK::Vec3& v_before) const;

    const ApproximationContext& context_;
    ApproxOptions options_;
    std::unique_ptr<MultiAttachmentSwitch> multi_;  // ApproxAttach::Multi: replaces the merge (c) and (d)
    std::vector<std::string> goalBodies_;  // body of each goal end-effector

    const RecordKeeper* keeper_ = nullptr;  // owned by the force subsystem
    const ObjectLoads* loads_ = nullptr;  // the run's external loads (setObjectLoads), or none
};

}  // namespace graspsim::simulation
