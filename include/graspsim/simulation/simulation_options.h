#pragma once
/// @file
/// What a user chooses per simulation run, on top of the scenario.

#include "graspsim/grasp/friction_limits.h"
#include "graspsim/simulation/ramp_load.h"

#include <array>
#include <optional>
#include <string>

namespace graspsim::scenario {
struct Scenario;
struct ApproximationSpec;
}

namespace graspsim::simulation {

/// How finger-object contact is modelled.
enum class ContactModel {
    Compliant,  ///< Hunt-Crossley normal force with Stribeck friction (contact::CompliantContactForce)
    Rigid       ///< unilateral contact with Coulomb friction (SemiExplicitEulerTimeStepper)
};

/// Whether the grasp approximation may replace the contacts.
enum class SimulationMode {
    Full,   ///< every contact solved all the time (the ground truth)
    Approx  ///< the grasp approximation (one 6-DOF constraint once the grasp is firm)
};

/// Which integrator advances the simulation.
enum class IntegratorChoice {
    /// The default: LinearlyImplicit where it has the analytic Jacobian of every stiff element
    /// (full compliant contact, the merged bushing), SimbodyCpodes elsewhere (resolveIntegrator)
    Automatic,
    SimbodyCpodes,  ///< Simbody's CPodes (BDF, Newton), stepped as by SimTK::TimeStepper (simbody_stepper.h)
    Cvode,          ///< SUNDIALS CVODE (BDF, Newton), the reference (integration/cvode_integrator.h)
    /// Linearly implicit two-stage Rosenbrock (ROS2) with analytic contact and joint force
    /// Jacobians (integration/linearly_implicit_stepper.h), steps up to stepSize chosen by error
    /// control at the accuracy; compliant contact only
    LinearlyImplicit,
    /// The same at fixed steps of stepSize (no error control)
    LinearlyImplicitFixed
};

/// Which realization of the friction-limited 6-DOF palm-object constraint the approximation uses.
enum class ApproxConstraint {
    Bushing,  ///< compliant: stiff spring-damper whose anchor slips at the limits (grasp::LimitedBushing)
    Weld      ///< rigid: per axis a stick constraint or, at the limit, the limit force (grasp::LimitedWeld)
};

/// How the end-effectors are attached to the object while the approximation is engaged.
enum class ApproxAttach {
    Merged,  ///< the thesis: fingers locked to the palm (one composite body), one palm-object element
    Multi    ///< one element spanning the object and every fingertip, fingers free (grasp::MultiAttachment)
};

/// An extra rule for releasing the approximation (`--release-at`; grasp_switch.h).
enum class ApproxReleaseTrigger {
    /// The default: Compliance where it applies (the merged bushing), None elsewhere
    /// (resolveApproxOptions decides).
    Automatic,
    None,  ///< only the switch's own rules (slide, penetration, goal distance, Q < Q_M): the thesis's
    /// also release once the constraint's reaction, or the load the grasp carries (gravity and the
    /// run's external loads on the object, GraspSwitch::setObjectLoads), reaches, on any axis side,
    /// the two-sided limit the grasp's compliance model predicts at engagement
    /// (grasp/compliance_limits.h, computed as for --limits compliance); the constraint keeps its
    /// own limits. Bushing and merged only.
    Compliance
};

/// In which state full contact takes the object back at a release of the compliance trigger.
enum class ApproxHandBack {
    Engaged,  ///< as the constraint holds it: the engaged pose, fingers at their engagement angles
    /// deflected as the grasp's compliance model says full contact would be under the load the
    /// constraint carried (deflected_hand_back.h): object displaced, finger joints bent
    Deflected
};

/// How the merged bushing gives under a load while engaged.
enum class ApproxBushingGive {
    Automatic,  ///< the default: Coupled on the merged bushing, Stiff otherwise
    Stiff,  ///< stiffened so that its deflection at its limits sinks no fingertip past the bound
    /// its rotational stiffness from the grasp's compliance model, rolling included (bushing_give.h),
    /// and preloaded with the contacts' wrench at engagement: the object turns in the palm under a
    /// load as the model says full contact's would, and the locked fingers follow it by their share
    /// (finger_follow.h); the translations stay stiff. Bushing and merged only.
    Model,
    /// as Model, with the model's whole sticking stiffness in place of its rotational diagonal: a
    /// 6 x 6 matrix that couples the rotations and the translations (bushing_give.h), so the object
    /// also shifts in the palm as the model says. Bushing and merged only.
    Coupled
};

/// Settings of the grasp switch of `--mode approx` (thesis Figure 4.1; see grasp_switch.h).
/// Defaults are this project's choices, documented where they are used.
struct ApproxOptions {
    /// Q_Th (N): engage when the full-contact grasp quality reaches it. 0 = the scenario's
    /// approximation.q_threshold, and if that is 0 too, automatic: autoThresholdFraction times
    /// the quality observed when the grasp first settles.
    double qThreshold = 0;
    /// Q_M (N): release when the engaged quality estimate falls below it; 0 = the scenario's
    /// approximation.q_minimum, and if that is 0 too, hysteresisFraction * Q_Th. Must be < Q_Th.
    double qMinimum = 0;
    /// Automatic Q_Th as a fraction of the settled grasp's quality. 0.8: engages on the settled
    /// grasp itself while leaving 20 % margin for the quality's ripple (the IK updates every
    /// ik_interval, and the quality follows the contact forces).
    double autoThresholdFraction = 0.8;
    /// Q_M as a fraction of Q_Th (hysteresis, so that one noisy sample does not toggle the switch).
    double hysteresisFraction = 0.5;
    /// Release once the object has moved more than this relative to the palm since engagement
    /// (m): about the radius of a fingertip pad, beyond which the fingers would have lost the
    /// spots they pressed into.
    double releaseSlideDistance = 0.005;
    /// Release once a replaced contact's depth has grown more than this beyond its depth at
    /// engagement (m). The locked fingers cannot give way as real contacts would, so an object
    /// sliding against a pad sinks into it; handed back later, the pad would throw the object out.
    double releasePenetration = 0.0005;
    /// Which friction coefficient the limits use: true the scenario's STATIC one, false the
    /// dynamic one; unset (default) the limit model's own: dynamic for the thesis's and the contact
    /// limits (static is opt-in, for comparing capacities: the compliant contact holds until the
    /// static coefficient), static for the compliance limits, whose model stands for full contact's
    /// regularized friction, which breaks loose at its static peak (docs/capacity.md).
    std::optional<bool> staticFrictionLimits;
    /// How the constraint's limits follow from the contacts at engagement: the thesis's box
    /// (default), per axis from each contact's normal and position (grasp/friction_limits.h), or
    /// two-sided per axis from the grasp's compliance model (grasp/compliance_limits.h; bushing
    /// and merged only).
    grasp::FrictionLimitModel limitModel = grasp::FrictionLimitModel::Thesis;
    /// Bound on the growth of the fingertips' penetration while engaged from the bushing's elastic
    /// deflection (m; the thesis's conclusion names fingertips sinking into the object as the
    /// approximation's visible flaw: 0.1 mm is not visible). On engagement the bushing
    /// is stiffened so that its deflection at the friction limits stays within it (grasp_switch.h).
    double maxEngagedPenetration = 1e-4;
    /// The constraint realization. Default bushing (the first one built; results measured so far
    /// use it); `weld` is the rigid one, closer to the thesis's Vortex constraint.
    ApproxConstraint constraint = ApproxConstraint::Bushing;
    /// The attachment variant. Multi needs the bushing realization and goals on bodies with contact
    /// geometry (multi_attachment_switch.h).
    ApproxAttach attach = ApproxAttach::Merged;
    /// Which constraint axes are relaxed (friction-limited); the others are locked (rigid). SpatialVec
    /// order, rotation x, y, z then translation x, y, z of the object frame. Unset (default): the
    /// scenario's approximation.relaxed_axes (whose default is all six).
    std::optional<std::array<bool, 6>> relaxedAxes;
    /// An extra release rule. Automatic (default): the compliance trigger on the merged bushing, where
    /// it brings the approximation's holding capacity to full contact's (docs/capacity.md), none on the
    /// weld and multi; None is the thesis's switch.
    ApproxReleaseTrigger releaseTrigger = ApproxReleaseTrigger::Automatic;
    /// The compliance trigger's onset (m, > 0): it hands the object back once the grasp's compliance
    /// model says full contact would have let the object give this much at the grasp goals under
    /// the load the constraint carries (on an axis side or along the load). Unset:
    /// kDefaultReleaseGive, the model's slip onset. Set, it needs the compliance trigger. Smaller
    /// gives hand back earlier (docs/capacity.md, "The release give": 1 mm brings 17 of the thesis
    /// scenes' 18 capacity cells within 10 % of full contact, but not the can, and the phone
    /// chatters on CPodes).
    std::optional<double> releaseGive;
    /// With the compliance trigger, also the creep watch (creep_release.h): hand back once the
    /// compliance model, followed in time with full contact's creep under the carried load, gives
    /// ApproxOptions::releaseGive. Unset: on. Set, it needs the compliance trigger.
    std::optional<bool> releaseCreep;
    /// The state full contact starts from at a compliance-trigger release (Engaged, the default;
    /// Deflected needs the compliance trigger).
    ApproxHandBack handBack = ApproxHandBack::Engaged;
    /// How the merged bushing gives under a load (Automatic, the default: Coupled on the merged
    /// bushing; docs/capacity.md, "The bushing's coupled give").
    ApproxBushingGive bushingGive = ApproxBushingGive::Automatic;
};

/// ApproxOptions::releaseGive's default (m): the model's slip onset, the capacity protocol's 2 mm.
/// The switch hands back where the model says full contact would start to slip; the thesis's
/// pushes, which full contact holds, stay engaged (at 1 mm the ball's f1 is handed back at once).
inline constexpr double kDefaultReleaseGive = 2e-3;

/// Per-run choices. Defaults: compliant full contact, no perturbation, the scenario's duration.
struct SimulationOptions {
    ContactModel contact = ContactModel::Compliant;
    SimulationMode mode = SimulationMode::Full;
    std::string perturbation = "none";  ///< "none" or the name of one of the scenario's perturbations
    double duration = 0;                ///< simulated time (s); 0 takes the scenario's
    ApproxOptions approx;               ///< used in SimulationMode::Approx only
    IntegratorChoice integrator = IntegratorChoice::Automatic;
    /// Integrator accuracy (relative tolerance; CVODE's atol and both integrators' constraint
    /// tolerance follow it); 0 takes the scenario's simulation.accuracy.
    double accuracy = 0;
    /// Longest (LinearlyImplicit) or fixed (LinearlyImplicitFixed) step (s); 0 takes the scenario's
    /// (findStepSize).
    double stepSize = 0;
    /// A load on the object growing in time (the holding-capacity protocol, ramp_load.h); unset: none.
    std::optional<LoadRampSpec> loadRamp;
};

/// Parses "compliant" or "rigid". @throws graspsim::InputError naming `source`, the value and the choices.
ContactModel parseContactModel(const std::string& text, const std::string& source);
/// Parses "full" or "approx". @throws graspsim::InputError naming `source`, the value and the choices.
SimulationMode parseSimulationMode(const std::string& text, const std::string& source);
/// Parses "auto", "simbody", "cvode", "implicit" or "implicit-fixed". @throws graspsim::InputError naming `source`, the value and the choices.
IntegratorChoice parseIntegratorChoice(const std::string& text, const std::string& source);
std::string toString(ContactModel model);
std::string toString(IntegratorChoice integrator);
/// Parses "bushing" or "weld". @throws graspsim::InputError naming `source`, the value and the choices.
ApproxConstraint parseApproxConstraint(const std::string& text, const std::string& source);
std::string toString(ApproxConstraint constraint);
std::string toString(SimulationMode mode);
/// Parses "merged" or "multi". @throws graspsim::InputError naming `source`, the value and the choices.
ApproxAttach parseApproxAttach(const std::string& text, const std::string& source);
std::string toString(ApproxAttach attach);
/// Parses "auto", "none" or "compliance". @throws graspsim::InputError naming `source`, the value and the choices.
ApproxReleaseTrigger parseApproxReleaseTrigger(const std::string& text, const std::string& source);
std::string toString(ApproxReleaseTrigger trigger);
/// Parses "engaged" or "deflected". @throws graspsim::InputError naming `source`, the value and the choices.
ApproxHandBack parseApproxHandBack(const std::string& text, const std::string& source);
std::string toString(ApproxHandBack handBack);
/// Parses "stiff" or "model". @throws graspsim::InputError naming `source`, the value and the choices.
ApproxBushingGive parseApproxBushingGive(const std::string& text, const std::string& source);
std::string toString(ApproxBushingGive give);

/// Whether the scene of `scenario` supports `options.approx.attach` in approx mode: multi needs
/// the bushing realization, and every goal end-effector on a body with contact geometry; and
/// whether the limit model fits the attachment: compliance limits are two-sided, which only the
/// merged bushing takes; so does the compliance release trigger. Call before anything is written.
/// @throws graspsim::InputError naming --attach, --limits or --release-at otherwise.
void checkApproxAttach(const scenario::Scenario& scenario, const SimulationOptions& options);

/// Largest step / anchor_relaxation_time of the fixed-step linearly implicit integrator with the
/// anchor friction law: the anchors' relaxation is integrated explicitly, by ROS2's two-stage
/// explicit part, whose stability interval on the negative real axis ends at -2.
constexpr double kAnchorStabilityLimit = 2.0;

/// The fixed step (s) of IntegratorChoice::LinearlyImplicitFixed where neither the run nor the
/// scenario gives one: every shipped scene holds at it, where 2 ms and longer blow some up
/// (docs/performance.md, "Fixed steps that cannot be trusted").
constexpr double kDefaultFixedStepSize = 1e-3;

/// The linearly implicit stepper's step, and where it came from.
struct StepSizeChoice {
    double step = 0;     ///< s: the longest with error control, the step with implicit-fixed
    std::string source;  ///< for messages: "--step-size", "<scenario source>: simulation.step_size" or the default's
};

/// `options.stepSize` if > 0, else the scenario's simulation.step_size if > 0, else with error
/// control the controller's ik_interval (its events come that often, so a longer step would end on
/// them anyway) and with `options.integrator` IntegratorChoice::LinearlyImplicitFixed
/// kDefaultFixedStepSize.
StepSizeChoice findStepSize(const scenario::Scenario& scenario, const SimulationOptions& options);

/// The integrator a run of `scenario` with `options` uses: `options.integrator` unless it is
/// Automatic, which is LinearlyImplicit for compliant contact with the regularized friction law in
/// full mode and with the merged bushing (its steps at the cap cost 4-5x less than CPodes's on the
/// thesis scenes, and an engaged hold under a minute too: docs/performance.md), and SimbodyCpodes
/// for the weld and the multi attachment (constraints and per-finger bushings the stepper has no
/// Jacobian of: 10x more steps), for the anchor friction law (whose anchors it integrates
/// explicitly: the held phone keeps shaking, 0.1 m/s^2 after 3.5 s) and for rigid contact (which
/// runs its own stepper and ignores it).
IntegratorChoice resolveIntegrator(const scenario::Scenario& scenario, const SimulationOptions& options);

/// Whether `options.integrator` can run the scenario: not with rigid contact, which has its own
/// stepper (only auto and simbody are accepted there); and a fixed step (IntegratorChoice::
/// LinearlyImplicitFixed, at findStepSize's step) must be stable with
/// the scenario's friction law: with the anchor law at most kAnchorStabilityLimit x its relaxation
/// time (measured on the ball clutch at the default 1 ms: 2 ms runs, 2.5 ms blows up; at 2 ms
/// relaxation: 4 ms runs, 5 ms blows up). Error-controlled integrators pass: CPodes and CVODE
/// control every state's error; the error-controlled linearly implicit stepper controls q and u
/// only, so with the anchor law its longest step is capped at the same limit (makeSceneStepper).
/// Call before anything is written. @throws graspsim::InputError naming the
/// field (--integrator, --step-size or the file's simulation.step_size), its value and what is
/// accepted.
void checkIntegratorChoice(const scenario::Scenario& scenario, const SimulationOptions& options);

/// The approximation's options of a run: `given` over the scenario's `approximation:` section (a
/// threshold or relaxed axes given to the run win; 0 / unset take the scenario's), checked, before
/// anything is built (grasp_approximation.h takes only resolved options).
/// An Automatic release trigger becomes Compliance on the merged bushing and None otherwise; an
/// Automatic bushing give becomes Model on the merged bushing and Stiff otherwise.
/// @throws graspsim::InputError for a negative threshold, Q_M not below a given Q_Th, or a slide
///         distance or penetration bound <= 0.
ApproxOptions resolveApproxOptions(const ApproxOptions& given, const scenario::ApproximationSpec& scenario);

}  // namespace graspsim::simulation
