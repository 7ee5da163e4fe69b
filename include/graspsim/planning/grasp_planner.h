#pragma once
/// @file
/// Grasp planning: given a subject, an object and a grasp type, find the arm and hand joint
/// angles, the object's placement and the fingertip goal points of a grasp.
///
/// Grasp types follow Feix et al. (2016), "The GRASP Taxonomy of Human Grasp Types", IEEE
/// Trans. Human-Machine Systems 46(1):66-77 (see grasp_type.h). The method (docs/planning.md):
///  1. The arm joints stay at a fixed posture per grasp type (the thesis's hand-found poses:
///     ball-clutch for power grasps, phone-pinch for precision grasps); the fingers start from
///     that pose too. So the object is within reach by construction: it is placed against the
///     hand, wherever the hand is.
///  2. The object starts at the point its goal pads' normals meet (least squares) and is turned
///     so that its thinnest dimension lies along the squeeze.
///  3. NLopt's BOBYQA (deterministic, derivative free) moves the 20 finger and thumb joints
///     (bounded by their ranges of motion) and the object's position (and orientation, unless it
///     is a sphere) to minimize, per goal pad, (signed distance to the surface - targetGap)^2 and
///     the pad normal's misalignment with the inward surface normal, plus penalties for any
///     segment within clearance of the object (contact::findContacts) and a small pull toward the
///     start pose.
///  4. Goals are the surface points nearest each pad (contact::findSurfacePoint). The plan is
///     checked (PlanDiagnostics); a plan failing a check is refused with NoGraspError, except
///     that a box or convex mesh is first planned again from the optimum of its smooth stand-in
///     (the ellipsoid of its extents, optimized from the same start: a box's edges stop the
///     optimizer where the ellipsoid turns through), and that plan kept if it passes.
/// The object is handled only through contact::findSurfacePoint and contact::findContacts, so
/// every shape the contact layer knows can be planned for.
///
/// Frames: G Ground (the arm model's world), O the object frame (at its centre of mass), S the
/// object's contact shape frame (X_OS, usually identity).

#include "graspsim/simbody.h"

#include "graspsim/contact/contact_parameters.h"
#include "graspsim/contact/contact_shape.h"
#include "graspsim/error.h"
#include "graspsim/model/build_options.h"
#include "graspsim/planning/grasp_type.h"
#include "graspsim/scenario/scenario.h"

#include <map>
#include <string>
#include <vector>

namespace graspsim::planning {

/// No grasp of the requested type exists for this subject and object; the message says why,
/// with numbers ("object width 150 mm exceeds the hand's thumb-index span 118 mm"). An
/// InputError: the CLI exits with code 2.
class NoGraspError : public InputError {
public:
    explicit NoGraspError(const std::string& message) : InputError(message) {}
};

/// What to plan: whose arm, which object, which grasp.
struct GraspRequest {
    model::BuildOptions bodyOptions = scenario::Scenario::makeDefaultBodyOptions();  ///< subject and preset
    contact::ContactShape shape;                ///< the object's surface, in its shape frame S
    SimTK::Transform X_OS;                      ///< shape frame in the object frame O (usually identity)
    GraspType type = GraspType::PowerSphere;
    double targetGap = 0.0015;                  ///< wanted pad-to-surface distance in the plan (m), > 0
    double pressDepth = 0.002;                  ///< the controller's press depth (m): goals are reached this far inside
    double mass = 0.2;                          ///< the object's mass (kg): what the fingers carry once it is released
    SimTK::Vec3 gravity{0, -9.81, 0};           ///< gravity in G (m/s^2): the pads should not push along it
};

/// One goal end-effector of a plan, as planned.
struct GoalCheck {
    std::string effector;     ///< e.g. "index_tip"
    double gap = 0;           ///< signed distance of its pad point to the surface (m)
    double misalignment = 0;  ///< angle between the pad's outward normal and the inward surface normal (rad)
    double reachShortfall = 0;///< the controller's IK from the plan ends this far from the goal pressed pressDepth in (m), goal_reach.h
    double commandedPress = 0;///< how deep inside the surface that IK solution puts the pad (m): what makes the finger press
    /// How deep the finger's end segment reaches into the object where the controller (the plan's
    /// kp) and the joints' passive springs balance, the object out of the way (m, 0 if it stays
    /// outside; goal_reach.h): what the finger actually presses. The pad point alone understates an
    /// oblique pad, whose segment touches beside it first.
    double steadyPress = 0;
    /// What the finger still presses once the object is released and has settled, as the planner
    /// predicts it (m, 0: it lets go; release_press.h).
    double releasedPress = 0;
};

/// How good the plan is: the numbers its checks look at.
struct PlanDiagnostics {
    std::vector<GoalCheck> goals;   ///< in the template's effector order
    double maxPenetration = 0;      ///< deepest overlap of any arm or hand segment with the object (m), 0 if none
    std::string deepestSegment;     ///< that segment's geometry name, empty if none
    double quality = 0;             ///< Q, smallest singular value of the grasp matrix of the goal contacts (N per N)
    bool antipodal = false;         ///< two-contact grasps: the contact line inside both friction cones
    /// Two-contact grasps: the larger of the angles between the line joining the contacts and
    /// each contact's inward surface normal (rad); antipodal when below frictionConeAngle. 0 for
    /// other grasps, which are checked by Q.
    double antipodalAngle = 0;
    double frictionConeAngle = 0;   ///< two-contact grasps: the check's friction cone half-angle, atan(0.7) (rad)
    double objectWidth = 0;         ///< the object's thinnest width (m)
    double handSpan = 0;            ///< the hand's span for this grasp type (m)
    int evaluations = 0;            ///< objective evaluations the optimizer used
    double cost = 0;                ///< final objective value (dimensionless)
};

/// A planned grasp. Angles in rad, lengths in m.
struct GraspPlan {
    GraspType type = GraspType::PowerSphere;
    std::map<std::string, double> jointAngles;   ///< every arm and hand joint of the model (rad)
    /// Object pose in G at t = 0; planGrasp rounds it (position to 0.1 mm, body-fixed X-Y-Z
    /// angles to 0.1 deg, plan_rounding.h), as it rounds the joint angles (0.1 deg) and goals (0.1 mm).
    SimTK::Transform X_GO;
    std::vector<std::string> goalEffectors;      ///< thumb first, then index to little
    std::map<std::string, SimTK::Vec3> goals;    ///< goal point on the surface per effector, in O (m)
    double kp = 5;                               ///< suggested finger PD gain (N m/rad)
    /// The template's capsule rule (GraspTemplate::capsuleContact); applyPlan writes Ends into the
    /// scenario and leaves the scenario's rule for Deepest.
    contact::CapsuleContact capsuleContact = contact::CapsuleContact::Deepest;
    /// The controller's press depth the plan is made for (m): the request's, or deeper when the
    /// passive springs and the release would leave a goal finger less than half of it; 0: the
    /// request's (a plan not made by planGrasp).
    double pressDepth = 0;
    /// End-effectors the plan adds to the body model (lateral: the index's radial side), which
    /// `goals` may name; empty for fingertip-pad grasps.
    std::vector<model::SegmentPoint> segmentPoints;
    PlanDiagnostics diagnostics;
};

/// Plan-check thresholds (m, rad).
struct PlanTolerances {
    double minGap = 0.0;          ///< pads must not be inside the object
    double maxGap = 0.005;        ///< "within a few mm of the surface"
    double maxMisalignment = 1.134; ///< pad facing the surface: within 65 deg (the thesis's hand-found ball clutch, which holds, has 62)
    double maxPenetration = 0.001;///< no segment deeper than 1 mm in the object
    /// The set-up check's reach limit (simulation::kGoalReachTolerance, setup_check.h): the
    /// controller's IK from the plan must end within this of each goal pressed pressDepth inside,
    /// so a planned scenario is never refused by the check.
    double maxReachShortfall = 0.003;
    /// Each goal pad's IK solution must lie at least this deep inside the object (m): a pad the IK
    /// leaves at the surface (on a rim, or with a joint at its limit) never presses, its finger
    /// leaves the object once it settles, and the approximation, which engages on full contact,
    /// never does. An eighth of the 2 mm press; the planned grasps of the study's tables command
    /// 0.34 mm (a tripod thumb on a 15 mm ball) or more.
    double minCommandedPress = 0.00025;
};

/// Plans the grasp. Deterministic: the same request gives the same plan, bit for bit.
/// @throws NoGraspError when the object does not fit the hand for this type, or the best pose
///         found fails a check (the message names the check and its numbers).
/// @throws InputError for an invalid shape or subject.
GraspPlan planGrasp(const GraspRequest& request, const PlanTolerances& tolerances = {});

/// The press depth a plan for `scenario` uses (m): the scenario's, or for an object thinner than
/// twice it (a card, a key), half the object's half-thickness, rounded to 0.1 mm.
double findPlannedPressDepth(const scenario::Scenario& scenario);

/// The object of a scenario as the planner's shape: the object body's (only) geometry.
/// @throws InputError if the contact layer has no shape for it.
GraspRequest makeGraspRequest(const scenario::Scenario& scenario, GraspType type);

/// The two-contact closure check of `diagnostics` in words, with its figures in degrees:
/// "antipodal (contact line 2.5 deg off the normals, friction cone 35.0 deg)", or "not antipodal (...)".
std::string describeAntipodal(const PlanDiagnostics& diagnostics);

/// Re-evaluates a plan's numbers (gaps, misalignments, penetration, Q) for joint angles, object
/// pose and goal effectors as they stand, e.g. after rounding.
PlanDiagnostics calcPlanDiagnostics(const GraspRequest& request, const GraspPlan& plan);

/// The first failed check of `diagnostics`, as one line with its numbers, or "" if all pass.
std::string findFailedCheck(const PlanDiagnostics& diagnostics, const PlanTolerances& tolerances);

}  // namespace graspsim::planning
