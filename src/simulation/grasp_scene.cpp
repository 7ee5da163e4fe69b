#include "graspsim/simulation/grasp_scene.h"

#include "graspsim/contact/hand_object_pairs.h"
#include "graspsim/error.h"
#include "graspsim/model/body_model.h"
#include "graspsim/system/simtk_conversion.h"

#include <algorithm>
#include <cmath>

namespace graspsim::simulation {

namespace {

system::SystemOptions makeSystemOptions(const scenario::Scenario& s) {
    system::SystemOptions options;
    options.gravity = system::toSimTKVec3(s.world.gravity);
    return options;
}

// The body that carries the fingertip goals (see grasp_controller.h).

using system::toSimTKVec3;

SimTK::Transform findObjectPose(const scenario::Scenario& s) {
    return system::toSimTKTransform(s.object.findPose(), "object pose");
}

// The movable joints from the palm out to an end-effector's body (the digit's own joints).
std::vector<std::string> findFingerJoints(const model::ModelDescription& d, const std::string& endEffector) {
    std::vector<std::string> joints;
    std::string body = d.findEndEffector(endEffector)->body;
    const auto isPalm = [&](const std::string& name) { return d.findBody(name)->role == model::BodyRole::Palm; };
    while (!isPalm(body)) {
        const model::Joint* j = d.findParentJoint(body);
        if (!j) throw Error("end-effector '" + endEffector + "' does not hang from a palm");
        if (j->type != model::Joint::Type::Fixed) joints.push_back(j->name);
        body = j->parent;
    }
    return joints;
}

}  // namespace

GraspScene::GraspScene(const scenario::Scenario& scenario, const SimulationOptions& options)
    : scenario_(scenario),
      model_(model::buildBodyModel(scenario.bodyOptions), makeSystemOptions(scenario)),
      contactModel_(options.contact),
      palmBody_(model_.getDescription().findPalm().name) {
    if (options.contact == ContactModel::Rigid && options.mode == SimulationMode::Approx) {
        throw InputError("--mode approx: not available with --contact rigid (the grasp switch is an event handler, "
                         "and the rigid stepper runs none); use --mode full or --contact compliant");
    }
    checkApproxAttach(scenario, options);
    checkIntegratorChoice(scenario, options);
    addObject(options.mode == SimulationMode::Approx && options.approx.attach != ApproxAttach::Multi &&
              options.approx.constraint == ApproxConstraint::Weld);
    addContacts();
    addController(options);
    if (contactModel_ == ContactModel::Rigid) addImplicitImpedance();
    model_.realizeTopology();
}

// On the palm for the weld, so that the weld can hold it by a lock (limited_weld.h); then a Weld
// constraint to Ground, not a lock, holds it until its release.
void GraspScene::addObject(bool onPalm) {
    const model::ModelDescription objectModel = scenario::buildObjectModel(scenario_.object);
    const model::Body& b = objectModel.bodies.at(0);
    const SimTK::Vec3 p_OCm = toSimTKVec3(b.p_BCm);
    const SimTK::Inertia I_Cm(b.inertia.xx, b.inertia.yy, b.inertia.zz, b.inertia.xy, b.inertia.xz, b.inertia.yz);
    const SimTK::Body::Rigid body(SimTK::MassProperties(b.mass, p_OCm, I_Cm.shiftFromMassCenter(p_OCm, b.mass)));
    SimTK::MobilizedBody& parent = onPalm ? updPalm() : model_.updMatter().updGround();
    object_ = SimTK::MobilizedBody::Free(parent, SimTK::Transform(), body, SimTK::Transform());
    SimTK::Constraint::Weld groundWeld;  // empty unless the object hangs from the palm
    if (onPalm) {
        groundWeld = SimTK::Constraint::Weld(model_.updMatter().updGround(), findObjectPose(scenario_),
                                             object_, SimTK::Transform());
    }
    hold_ = ObjectHold(object_, groundWeld);
}

void GraspScene::addContacts() {
    const model::ModelDescription objectModel = scenario::buildObjectModel(scenario_.object);
    const std::vector<contact::ContactPair> pairs =
        contact::makeHandObjectPairs(model_, contact::isHandSegmentBody, object_, objectModel.bodies.at(0),
                                     getContactParameters());
    if (contactModel_ == ContactModel::Rigid) {
        rigidContacts_ = contact::RigidContactSet(model_.updMatter(), pairs);
        return;
    }
    contacts_ = contact::CompliantContactForce(model_.updForces(), pairs, scenario_.friction);
}

// Every movable joint's linear impedance: passive spring and damper, the PD gains (the
// controller drives every movable joint), and its limit stop.
std::vector<system::JointImpedance> GraspScene::findJointImpedances() const {
    std::vector<system::JointImpedance> joints;
    const std::vector<std::string>& controlled = pd_->getJointNames();
    for (const std::string& name : model_.getJointNames()) {
        const model::Joint& j = *model_.getDescription().findJoint(name);
        system::JointImpedance impedance{model_.getMobilizedBody(j.child).getMobilizedBodyIndex(), j.stiffness,
                                         j.damping, model_.getPassiveJointForces(name).getStop()};
        const auto it = std::find(controlled.begin(), controlled.end(), name);
        if (it != controlled.end()) {
            const control::PdGains& gains = pd_->getGains()[static_cast<std::size_t>(it - controlled.begin())];
            impedance.stiffness += gains.kp;
            impedance.damping += gains.kd;
        }
        joints.push_back(impedance);
    }
    return joints;
}

void GraspScene::addImplicitImpedance() {
    impedance_ = system::ImplicitJointImpedance(model_.updForces(), model_.getMatter(), findJointImpedances());
}

std::vector<contact::ContactReport> GraspScene::findContactReports(const SimTK::State& state) const {
    if (contactModel_ == ContactModel::Rigid) return rigidContacts_.findContactReports(state);
    return contacts_.findContactReports(state);
}

const SimTK::MobilizedBody& GraspScene::getPalm() const { return model_.getMobilizedBody(palmBody_); }

SimTK::MobilizedBody& GraspScene::updPalm() { return model_.updMatter().updMobilizedBody(getPalm().getMobilizedBodyIndex()); }

void GraspScene::addController(const SimulationOptions& options) {
    const model::ModelDescription& d = model_.getDescription();
    std::vector<control::ControlledJoint> joints;
    std::vector<std::string> armBodies;
    for (const model::Joint& j : d.joints) {
        if (j.type == model::Joint::Type::Fixed) continue;
        const bool finger = d.findBody(j.child)->role == model::BodyRole::Digit;
        joints.push_back({j.name, finger ? control::PdGains{scenario_.controller.kp, scenario_.controller.kd}
                                         : control::PdGains{kArmKp, kArmKd}});
        if (finger) fingerMobilizers_.push_back(model_.getMobilizedBody(j.child).getMobilizedBodyIndex());
    }
    for (const model::Body& b : d.bodies) armBodies.push_back(b.name);
    pd_ = std::make_unique<control::JointPdController>(model_, joints, armBodies);

    std::vector<std::string> ikJoints;
    goals_ = FingertipGoals(model_, object_);
    for (const auto& [endEffector, p_OT] : scenario_.goals) {
        for (const std::string& j : findFingerJoints(d, endEffector)) ikJoints.push_back(j);
        goals_.add(endEffector, toSimTKVec3(p_OT));
    }
    model_.realizeTopology();  // Simbody's Assembler (inside the IK) needs a realized topology
    ik_ = std::make_unique<control::FingertipIk>(model_, goals_.getEndEffectors(), ikJoints);
    const double ikInterval = scenario_.controller.ikInterval;
    controller_ = new control::GraspController(*pd_, *ik_, ikJoints, getPalm(), ikInterval, ikTiming_);
    if (options.mode == SimulationMode::Full) {
        model_.updSystem().addEventHandler(controller_);
        return;
    }
    // Approx: the grasp switch on top of the scene runs the IK while the grasp is not
    // approximated, so that it can pause it.
    ownedController_.reset(controller_);
}

SimTK::State GraspScene::makeInitialState() {
    SimTK::State state = model_.getSystem().getDefaultState();
    SimTK::Vector targets(static_cast<int>(pd_->getJointNames().size()), 0.0);
    for (std::size_t k = 0; k < pd_->getJointNames().size(); ++k) {
        const auto it = scenario_.graspPose.find(pd_->getJointNames()[k]);
        if (it == scenario_.graspPose.end()) continue;
        model_.setJointPosition(state, it->first, it->second);
        targets[static_cast<int>(k)] = it->second;
    }
    pd_->setTargets(state, targets);
    placeObject(state);
    model_.getSystem().realize(state, SimTK::Stage::Position);
    // The goals T: the scenario's points on the object, pressed in along the inward normal, as they
    // sit in the palm frame now that hand and object are in place.
    const SimTK::Transform X_HG = ~model_.getMobilizedBody(palmBody_).getBodyTransform(state);
    const SimTK::Transform& X_GO = object_.getBodyTransform(state);
    std::vector<control::FingertipGoal> goals;
    for (std::size_t k = 0; k < goals_.getEndEffectors().size(); ++k) {
        const SimTK::Vec3& onSurface = goals_.getSurfacePoints()[k];
        const model::Vec3 n_O = scenario_.object.findOutwardNormal({onSurface[0], onSurface[1], onSurface[2]});
        const SimTK::Vec3 p_OT = onSurface - scenario_.controller.pressDepth * toSimTKVec3(n_O);
        goals.push_back({goals_.getEndEffectors()[k], X_HG * (X_GO * p_OT)});
    }
    controller_->setGoals(goals);
    controller_->updateTargets(state);
    setupCheck_ = calcSetupCheck(*this, state);
    requireSetup(setupCheck_, scenario_.source.empty() ? "scenario " + scenario_.name : scenario_.source);
    return state;
}

// At the scenario's pose in Ground, held there: by a lock on Ground, or by the Ground weld when the
// object hangs from the palm (its coordinates then depend on where the grasp pose put the palm).
void GraspScene::placeObject(SimTK::State& state) const {
    const SimTK::Transform X_GO = findObjectPose(scenario_);
    if (!hold_.isByGroundWeld()) {
        object_.setQToFitTransform(state, X_GO);
        object_.lock(state, SimTK::Motion::Position);
        return;
    }
    model_.getSystem().realize(state, SimTK::Stage::Position);
    object_.setQToFitTransform(state, ~getPalm().getBodyTransform(state) * X_GO);
}

}  // namespace graspsim::simulation
