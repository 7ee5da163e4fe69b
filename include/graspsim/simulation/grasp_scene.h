#pragma once
/// @file
/// The scene of a grasp experiment in Simbody: the arm and hand, the free object, finger-object
/// contact and the PD + IK grasp controller with its fingertip goals.
///
/// The thesis's sequence (Figure 4.1): the hand is put in the grasp pose kinematically at t = 0
/// ("forward kinematics once"); IK then tracks the fingertips to goal points just inside the
/// object's surface so the fingers press. The object is held in place until the scenario's
/// approach time, when it is released and only the grasp holds it.
///
/// The object's mobilizer is Free, from Ground (held by locking it) except with the merged weld:
/// there it is Free from the palm, so that the engaged weld can hold it by locking that mobilizer
/// instead of solving six constraint equations (grasp::LimitedWeld, "held by a lock"), and a
/// SimTK::Constraint::Weld to Ground holds it until its release (to the integrator's constraint
/// tolerance where the lock is exact: a few micrometres by the release in the built-in scenarios).
/// After the release the object is the same free rigid body either way; only its coordinates differ.
///
/// The scene is what full contact needs of a run. The approximation (its attachment and grasp
/// switch, grasp_approximation.h) and the loads on the object (object_loads.h) are built on top of
/// it, in that order (grasp_experiment.h); the scene knows nothing of them. In
/// SimulationMode::Approx it only leaves its IK controller out of the System, for the grasp switch
/// to run, and with the merged weld hangs the object from the palm (above).
///
/// With ContactModel::Rigid the finger-object pairs are rigid contacts (contact::RigidContactSet)
/// instead of the compliant force element, and the joints' impedance (passive spring, damper,
/// stop, PD gains) is integrated implicitly by a system::ImplicitJointImpedance (off until a
/// step size is set; see rigid_stepping.h). The IK controller is still a periodic event
/// handler, but Simbody's SemiExplicitEulerTimeStepper runs no event handlers: the rigid
/// stepping calls it (getController()).

#include "graspsim/contact/compliant_contact_force.h"
#include "graspsim/contact/rigid_contact_set.h"
#include "graspsim/control/grasp_controller.h"
#include "graspsim/scenario/scenario.h"
#include "graspsim/simulation/fingertip_goals.h"
#include "graspsim/simulation/object_hold.h"
#include "graspsim/simulation/setup_check.h"
#include "graspsim/simulation/simulation_options.h"
#include "graspsim/system/implicit_joint_impedance.h"
#include "graspsim/system/multibody_model.h"

#include "graspsim/simbody.h"

#include <memory>
#include <string>
#include <vector>

namespace graspsim::simulation {

/// Arm joints (shoulder to wrist) hold the grasp pose with these PD gains on top of gravity
/// compensation: stiff enough that a 10 N perturbation on the object moves the wrist by
/// millimetres, so the hand, not the arm, decides whether the object slips.
constexpr double kArmKp = 200.0;  ///< N m/rad
constexpr double kArmKd = 20.0;   ///< N m s/rad

/// The scene (see the file comment). Neither copyable nor movable (Simbody elements refer into it).
class GraspScene {
public:
    /// @throws graspsim::InputError for an unsupported option (approx with rigid contact, multi where it cannot attach).
    GraspScene(const scenario::Scenario& scenario, const SimulationOptions& options);
    GraspScene(const GraspScene&) = delete;
    GraspScene& operator=(const GraspScene&) = delete;

    const scenario::Scenario& getScenario() const { return scenario_; }
    /// The parameters of every finger-object contact pair, as the contact elements were given
    /// them (the scenario's `contact:` section). The approximation takes its friction limits, its
    /// sticking speed and the grasp quality's mu from here.
    const contact::ContactParameters& getContactParameters() const { return scenario_.contact; }
    const system::MultibodyModel& getModel() const { return model_; }
    /// The model, for the elements built on top of the scene (grasp_experiment.h), which call
    /// realizeTopology() again after adding theirs.
    system::MultibodyModel& updModel() { return model_; }
    const SimTK::MultibodySystem& getSystem() const { return model_.getSystem(); }
    /// The object's body; its frame O is at its centre of mass.
    const SimTK::MobilizedBody& getObject() const { return object_; }
    /// The compliant contact element; an empty handle with ContactModel::Rigid.
    const contact::CompliantContactForce& getCompliantContacts() const { return contacts_; }
    ContactModel getContactModel() const { return contactModel_; }
    /// The rigid contacts; empty with ContactModel::Compliant.
    const contact::RigidContactSet& getRigidContacts() const { return rigidContacts_; }
    /// The implicit joint impedance element; an empty handle with ContactModel::Compliant.
    const system::ImplicitJointImpedance& getImpedance() const { return impedance_; }
    /// Every movable joint's linear impedance (passive spring and damper, PD gains, limit stop):
    /// what implicit steppers treat implicitly.
    std::vector<system::JointImpedance> findJointImpedances() const;
    /// Every finger-object contact at `state` with its forces, from the contact model in use
    /// (rigid: from the multipliers of the step that produced `state`). Needs Stage::Velocity.
    std::vector<contact::ContactReport> findContactReports(const SimTK::State& state) const;
    /// The IK grasp controller: an event handler of the System in full mode; in approx mode the
    /// grasp switch runs it (and steppers that run no event handlers call it).
    const control::GraspController& getController() const { return *controller_; }
    const control::IkTiming& getIkTiming() const { return ikTiming_; }
    /// Names of the end-effectors that have goals, in goal order.
    const std::vector<std::string>& getGoalEndEffectors() const { return goals_.getEndEffectors(); }
    /// The goals on the object's surface (not pressed in), in O (m), in goal order.
    const std::vector<SimTK::Vec3>& getSurfaceGoals() const { return goals_.getSurfacePoints(); }
    /// The goals with the fingertip-goal distance.
    const FingertipGoals& getFingertipGoals() const { return goals_; }
    /// How the object is held until its release.
    const ObjectHold& getObjectHold() const { return hold_; }
    /// The palm: frame H of the approximation's bushing and the goals' frame.
    const SimTK::MobilizedBody& getPalm() const;
    /// Mobilizers of the finger joints (the ones merged into the palm while the approximation
    /// is engaged).
    const std::vector<SimTK::MobilizedBodyIndex>& getFingerMobilizers() const { return fingerMobilizers_; }
    /// Largest distance between a goal's fingertip and its goal point on the object's surface
    /// (m): how far the object has left the hand. Realizes `state` to Stage::Position.
    double findMaxFingertipGoalDistance(const SimTK::State& state) const { return goals_.findMaxDistance(state); }

    /// The state at t = 0: grasp pose, object at its initial pose and held, IK targets set (an
    /// approximation's attachment is released afterwards: GraspExperiment::makeInitialState).
    /// Checks it (setup_check.h) and keeps what the check measured (getSetupCheck()).
    /// @throws graspsim::InputError when a segment starts inside the object or a goal is out of reach.
    SimTK::State makeInitialState();
    /// What the set-up check measured in the last makeInitialState() (empty before it).
    const SetupCheck& getSetupCheck() const { return setupCheck_; }
    /// Releases the object (unlocks its mobilizer, or disables the Ground weld that holds it): an
    /// Instance-stage change.
    void releaseObject(SimTK::State& state) const { hold_.release(state); }
    /// Whether the object is still held at its initial pose (not yet released). Any stage.
    bool isObjectHeld(const SimTK::State& state) const { return hold_.isHeld(state); }
    /// When the object is released (s).
    double getReleaseTime() const { return scenario_.controller.approachTime; }

private:
    void addObject(bool onPalm);
    void placeObject(SimTK::State& state) const;
    SimTK::MobilizedBody& updPalm();
    void addContacts();
    void addController(const SimulationOptions& options);
    void addImplicitImpedance();

    const scenario::Scenario& scenario_;
    system::MultibodyModel model_;
    SimTK::MobilizedBody::Free object_;
    ObjectHold hold_;
    ContactModel contactModel_ = ContactModel::Compliant;
    std::string palmBody_;  // the body with the palm role (the builder's, not found by name)
    contact::CompliantContactForce contacts_;
    contact::RigidContactSet rigidContacts_;
    system::ImplicitJointImpedance impedance_;
    std::unique_ptr<control::JointPdController> pd_;
    std::unique_ptr<control::FingertipIk> ik_;
    control::GraspController* controller_ = nullptr;  // owned by the system (full) or ownedController_ (approx)
    std::unique_ptr<control::GraspController> ownedController_;  // approx: run by the grasp switch, not the system
    std::vector<SimTK::MobilizedBodyIndex> fingerMobilizers_;
    control::IkTiming ikTiming_;
    FingertipGoals goals_;
    SetupCheck setupCheck_;
};

}  // namespace graspsim::simulation
