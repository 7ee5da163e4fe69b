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
};

/// Solves the controller's fingertip IK from `jointAngles` (rad, by joint name; missing = 0) for
/// the pressed goals, over the joints from the palm to each goal's end-effector, within their
/// ranges of motion. Returns, in the order of `goals`, where each end-effector ends.
/// @throws graspsim::InputError naming an unknown end-effector or joint.
std::vector<GoalReach> calcGoalReach(const model::BuildOptions& bodyOptions, const std::map<std::string, double>& jointAngles,
                                  const std::vector<PressedGoal>& goals);

}  // namespace graspsim::planning
