#pragma once
/// @file
/// Forward kinematics of a ModelDescription without Simbody: every body's pose in ground from
/// joint angles, so a recorded trajectory can be replayed from its joint angles alone.

#include "graspsim/model/model_description.h"

#include <map>
#include <string>
#include <vector>

namespace graspsim::viewer {

/// X_GB of every body of `model`, in model.bodies order (m). X_GC = X_GP * X_PJ * X_JC(q) with
/// X_JC(q) a rotation by q (rad) about the joint axis (revolute, continuous), a translation by q (m)
/// along it (prismatic) or the identity (fixed); the root is at model.X_GR. A joint missing from
/// `jointAngles` is at 0.
std::vector<model::Transform> calcBodyPoses(const model::ModelDescription& model,
                                            const std::map<std::string, double>& jointAngles);

}  // namespace graspsim::viewer
