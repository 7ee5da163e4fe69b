#include "graspsim/system/multibody_model.h"

#include <algorithm>
#include <utility>

#include "body_mobilizer.h"
#include "graspsim/error.h"

namespace graspsim::system {

namespace {

// Runs a Simbody call and turns a SimTK exception into a one-line graspsim::Error that starts
// with `context`; SimTK's own message names a source file and spans lines, so keep its text only.
template <class Call>
decltype(auto) callSimbody(const std::string& context, Call&& call) {
    try {
        return std::forward<Call>(call)();
    } catch (const SimTK::Exception::Base& e) {
        throw Error(context + ": Simbody: " + foldToOneLine(e.getMessageText()));
    }
}

}  // namespace

MultibodyModel::MultibodyModel(const model::ModelDescription& description,
                               const SystemOptions& options)
    : description_(description), options_(options), matter_(system_), forces_(system_) {
    // Also a joint that moves only massless bodies, and mass properties Simbody cannot hold.
    description_.validate("model '" + description_.name + "'");
    callSimbody(describe("gravity"),
                [&] { gravity_ = SimTK::Force::Gravity(forces_, matter_, options_.gravity); });
    addBodies();
    realizeTopology();
}

MultibodyModel::~MultibodyModel() = default;

std::string MultibodyModel::describe(const std::string& what) const {
    return "model '" + description_.name + "': " + what;
}

void MultibodyModel::addBodies() {
    const model::Body& root = description_.bodies.front();
    const SimTK::MobilizedBody rootMobod =
        callSimbody(describe("root body '" + root.name + "'"),
                    [&] { return addRootMobilizedBody(matter_, root, description_.X_GR); });
    bodyIndexByName_[root.name] = rootMobod.getMobilizedBodyIndex();
    // Simbody needs a parent before its children. Sweeping the joint list in order and taking
    // each joint once its parent exists keeps the description's order where it already is a
    // tree order, so the state's q follow the joints as written. validate() ruled out cycles.
    std::vector<bool> added(description_.joints.size(), false);
    for (std::size_t pending = added.size(); pending > 0;) {
        for (std::size_t i = 0; i < added.size(); ++i) {
            const model::Joint& joint = description_.joints[i];
            if (added[i] || !bodyIndexByName_.count(joint.parent)) continue;
            addBody(joint);
            added[i] = true;
            --pending;
        }
    }
}

void MultibodyModel::addBody(const model::Joint& joint) {
    const model::Body& child = *description_.findBody(joint.child);
    const std::string context = describe("joint '" + joint.name + "' to body '" + child.name + "'");
    callSimbody(context, [&] {
        SimTK::MobilizedBody& parent = matter_.updMobilizedBody(bodyIndexByName_.at(joint.parent));
        const SimTK::MobilizedBody mobod = addJointMobilizedBody(parent, joint, child);
        bodyIndexByName_[child.name] = mobod.getMobilizedBodyIndex();
        if (joint.getDofCount() == 0) return;
        JointEntry entry;
        entry.mobodIndex = mobod.getMobilizedBodyIndex();
        entry.passive = PassiveJointForces(forces_, mobod, joint, options_);
        movableJoints_.emplace(joint.name, std::move(entry));
    });
}

const SimTK::State& MultibodyModel::realizeTopology() {
    return callSimbody(describe("realizeTopology"), [&]() -> const SimTK::State& {
        const SimTK::State& defaultState = system_.realizeTopology();
        cacheStateIndices(defaultState);
        return defaultState;
    });
}

void MultibodyModel::cacheStateIndices(const SimTK::State& defaultState) {
    // q and u slots are assigned at Model stage, so read them from a Model-realized copy.
    SimTK::State state = defaultState;
    system_.realizeModel(state);
    jointNamesInQOrder_.clear();
    for (auto& [name, entry] : movableJoints_) {
        const SimTK::MobilizedBody& mobod = matter_.getMobilizedBody(entry.mobodIndex);
        entry.qIndex = mobod.getFirstQIndex(state);
        entry.uIndex = mobod.getFirstUIndex(state);
        jointNamesInQOrder_.push_back(name);
    }
    std::sort(jointNamesInQOrder_.begin(), jointNamesInQOrder_.end(),
              [&](const std::string& a, const std::string& b) {
                  return movableJoints_.at(a).qIndex < movableJoints_.at(b).qIndex;
              });
}

const SimTK::MobilizedBody& MultibodyModel::getMobilizedBody(const std::string& bodyName) const {
    const auto it = bodyIndexByName_.find(bodyName);
    if (it == bodyIndexByName_.end()) {
        throw InputError(describe("no body named '" + bodyName + "'"));
    }
    return matter_.getMobilizedBody(it->second);
}

const MultibodyModel::JointEntry& MultibodyModel::getJointEntry(
    const std::string& jointName) const {
    const auto it = movableJoints_.find(jointName);
    if (it == movableJoints_.end()) {
        throw InputError(describe("no movable joint named '" + jointName + "'"));
    }
    return it->second;
}

std::vector<std::string> MultibodyModel::getJointNames() const { return jointNamesInQOrder_; }

SimTK::QIndex MultibodyModel::getJointQIndex(const std::string& jointName) const {
    return getJointEntry(jointName).qIndex;
}

SimTK::UIndex MultibodyModel::getJointUIndex(const std::string& jointName) const {
    return getJointEntry(jointName).uIndex;
}

const PassiveJointForces& MultibodyModel::getPassiveJointForces(
    const std::string& jointName) const {
    return getJointEntry(jointName).passive;
}

double MultibodyModel::getJointPosition(const SimTK::State& state,
                                        const std::string& jointName) const {
    const SimTK::QIndex q = getJointQIndex(jointName);
    return callSimbody(describe("joint '" + jointName + "' position"),
                       [&] { return state.getQ()[q]; });
}

void MultibodyModel::setJointPosition(SimTK::State& state, const std::string& jointName,
                                      double value) const {
    const SimTK::QIndex q = getJointQIndex(jointName);
    callSimbody(describe("joint '" + jointName + "' position"), [&] { state.updQ()[q] = value; });
}

double MultibodyModel::getJointSpeed(const SimTK::State& state,
                                     const std::string& jointName) const {
    const SimTK::UIndex u = getJointUIndex(jointName);
    return callSimbody(describe("joint '" + jointName + "' speed"),
                       [&] { return state.getU()[u]; });
}

void MultibodyModel::setJointSpeed(SimTK::State& state, const std::string& jointName,
                                   double value) const {
    const SimTK::UIndex u = getJointUIndex(jointName);
    callSimbody(describe("joint '" + jointName + "' speed"), [&] { state.updU()[u] = value; });
}

SimTK::Vec3 MultibodyModel::findEndEffectorLocationInGround(
    const SimTK::State& state, const std::string& endEffectorName) const {
    const model::EndEffector* endEffector = description_.findEndEffector(endEffectorName);
    if (!endEffector) {
        throw InputError(describe("no end-effector named '" + endEffectorName + "'"));
    }
    const SimTK::MobilizedBody& mobod = getMobilizedBody(endEffector->body);
    const SimTK::Vec3 p_BE(endEffector->p_BE[0], endEffector->p_BE[1], endEffector->p_BE[2]);
    return callSimbody(describe("end-effector '" + endEffectorName + "'"),
                       [&] { return mobod.findStationLocationInGround(state, p_BE); });
}

double MultibodyModel::calcMechanicalEnergy(const SimTK::State& state) const {
    return callSimbody(describe("mechanical energy"), [&] { return system_.calcEnergy(state); });
}

double MultibodyModel::calcPassiveDissipationPower(const SimTK::State& state) const {
    return callSimbody(describe("dissipation power"), [&] {
        double power = 0;
        for (const auto& [name, entry] : movableJoints_) {
            power += entry.passive.calcDissipationPower(state);
        }
        return power;
    });
}

}  // namespace graspsim::system
