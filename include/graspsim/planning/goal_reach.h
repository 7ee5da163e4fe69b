#pragma once
/// @file
/// The set-up check's reach test, run by the planner on its own plan.
///
/// At t = 0 the grasp controller moves each goal press_depth inside the object along the inward
/// surface normal and solves the fingertip IK (control::FingertipIk, the same solver, joints and
/// bounds as the simulation's controller) from the grasp pose. The distance each end-effector is
/// left from its pressed goal is what simulation::requireSetup compares with its 3 mm limit, and
/// what decides how hard the finger presses: a finger short by d of a goal pressed p inside is
/// driven only p - d into the object, so a finger short by p or more does not press at all.
///
/// The PD controller does not reach the IK solution either: each joint's passive spring (stiffness
/// k toward its rest angle) holds it back, and the joint settles where kp (q_IK - q) = k (q - q_rest)
/// (gravity the controller cancels). For a 1.90 m man's finger flexed 40/30/17 deg at kp 10 that
/// is 2 mm at the pad, the whole press: the finger touches without pressing. The steady state
/// below is that pose, the object out of the way.

#include "graspsim/model/build_options.h"

#include "graspsim/simbody.h"

#include <map>
#include <string>
#include <vector>

namespace graspsim::planning {

/// One goal as the controller sees it at t = 0.
struct PressedGoal {
    std::string effector;  ///< e.g. "little_tip"
    SimTK::Vec3 p_GT;      ///< the goal pressed press_depth inside the surface, in Ground (m)
};

/// Where the controller's IK leaves one end-effector.
struct GoalReach {
    double shortfall = 0;  ///< distance from the end-effector to its pressed goal (m)
    SimTK::Vec3 p_GE{0, 0, 0};  ///< the end-effector in Ground at the IK solution (m)
    /// The end-effector in Ground where the controller (gain kp toward the IK solution) and the
    /// joints' passive springs balance, the object out of the way (m).
    SimTK::Vec3 p_GE_steady{0, 0, 0};
};

/// Every goal's reach, and the joint angles of the steady state (rad, by joint name: the given
/// angles with each digit joint moved to where kp and its passive spring balance).
struct GoalReachResult {
    std::vector<GoalReach> goals;
    std::map<std::string, double> steadyAngles;
};

/// Solves the controller's fingertip IK from `jointAngles` (rad, by joint name; missing = 0) for
/// the pressed goals, over the joints from the palm to each goal's end-effector, within their
/// ranges of motion. Returns, in the order of `goals`, where each end-effector ends, at the IK
/// solution and at the steady state of a controller with gain `kp` (N m/rad, > 0).
/// @throws graspsim::InputError naming an unknown end-effector or joint.
GoalReachResult calcGoalReach(const model::BuildOptions& bodyOptions, const std::map<std::string, double>& jointAngles,
                              const std::vector<PressedGoal>& goals, double kp);

}  // namespace graspsim::planning
