#include "graspsim/planning/goal_reach.h"

#include "graspsim/control/fingertip_ik.h"
#include "graspsim/error.h"
#include "graspsim/model/body_model.h"
#include "graspsim/system/multibody_model.h"

#include <algorithm>

namespace graspsim::planning {

namespace {

// The movable joints from the palm out to an end-effector's body: the joints the simulation's
// grasp controller gives its IK for that goal (simulation/grasp_scene.cpp).
std::vector<std::string> findDigitJoints(const model::ModelDescription& d, const std::string& effector) {
    const model::EndEffector* e = d.findEndEffector(effector);
    if (!e) throw InputError("the arm model has no end-effector '" + effector + "'");
    std::vector<std::string> joints;
    std::string body = e->body;
    while (d.findBody(body)->role != model::BodyRole::Palm) {
        const model::Joint* j = d.findParentJoint(body);
        if (!j) throw InputError("end-effector '" + effector + "' does not hang from a palm");
        if (j->type != model::Joint::Type::Fixed) joints.push_back(j->name);
        body = j->parent;
    }
    return joints;
}

// Where joint `j`, driven toward `target` by gain kp against its passive spring, settles (rad),
// within its range of motion.
double findSteadyAngle(const model::Joint& j, double target, double kp) {
    const double q = (kp * target + j.stiffness * j.restAngle) / (kp + j.stiffness);
    return j.hasLimits() ? std::clamp(q, j.lower, j.upper) : q;
}

}  // namespace

GoalReachResult calcGoalReach(const model::BuildOptions& bodyOptions, const std::map<std::string, double>& jointAngles,
                              const std::vector<PressedGoal>& goals, double kp) {
    if (!(kp > 0)) throw InputError("goal reach: the controller gain kp must be > 0 N m/rad");
    system::MultibodyModel model(model::buildBodyModel(bodyOptions));
    std::vector<std::string> effectors, joints;
    std::vector<SimTK::Vec3> goals_G;
    for (const PressedGoal& goal : goals) {
        for (const std::string& j : findDigitJoints(model.getDescription(), goal.effector)) joints.push_back(j);
        effectors.push_back(goal.effector);
        goals_G.push_back(goal.p_GT);
    }
    control::FingertipIk ik(model, effectors, joints);
    SimTK::State state = model.realizeTopology();
    for (const auto& [joint, angle] : jointAngles) model.setJointPosition(state, joint, angle);
    const SimTK::Vector q = ik.solve(state, goals_G);
    for (std::size_t k = 0; k < joints.size(); ++k) model.setJointPosition(state, joints[k], q[static_cast<int>(k)]);
    model.getSystem().realize(state, SimTK::Stage::Position);
    GoalReachResult result;
    for (std::size_t k = 0; k < goals.size(); ++k) {
        result.goals.push_back({ik.getLastDistances().at(k), model.findEndEffectorLocationInGround(state, goals[k].effector)});
    }
    result.steadyAngles = jointAngles;
    const model::ModelDescription& d = model.getDescription();
    for (std::size_t k = 0; k < joints.size(); ++k) {
        const double angle = findSteadyAngle(*d.findJoint(joints[k]), q[static_cast<int>(k)], kp);
        result.steadyAngles[joints[k]] = angle;
        model.setJointPosition(state, joints[k], angle);
    }
    model.getSystem().realize(state, SimTK::Stage::Position);
    for (std::size_t k = 0; k < goals.size(); ++k) {
        result.goals[k].p_GE_steady = model.findEndEffectorLocationInGround(state, goals[k].effector);
    }
    return result;
}

}  // namespace graspsim::planning
