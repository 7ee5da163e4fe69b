#pragma once
/// @file
/// The fixed part of each grasp type: the arm posture, the fingers' start pose, which
/// end-effectors hold the object, and the controller gain. The planner keeps the arm and wrist
/// at this posture and optimizes the fingers from the start pose.

#include "graspsim/contact/contact_parameters.h"
#include "graspsim/planning/grasp_type.h"

#include <map>
#include <string>
#include <vector>

namespace graspsim::planning {

/// A grasp type's template. Angles in rad by joint name of model::buildArmModel.
struct GraspTemplate {
    std::map<std::string, double> startPose;   ///< arm posture (kept) and finger start (optimized)
    std::vector<std::string> goalEffectors;    ///< end-effectors on the object, thumb first
    double kp = 5;                             ///< finger PD gain for the scenario (N m/rad)
    /// The capsule rule the grasp needs: Ends where a phalanx's side lies flat on the object
    /// (lateral), whose one deepest point would jump from end to end as the phalanx tilts;
    /// Deepest (fingertip pads) leaves the scenario's rule.
    contact::CapsuleContact capsuleContact = contact::CapsuleContact::Deepest;
    /// The goal pads' mean inward surface normal must point against gravity by at least this
    /// (a cosine, 0 = horizontal squeeze allowed): the fingers curl under the object, so their
    /// normal forces, not friction alone, carry part of its weight.
    double minSupport = 0;
    /// A planned finger joint stays this far inside its range of motion (rad), so that the
    /// controller can still move it both ways: a digit planned at a limit cannot press along the
    /// surface normal (the thumb planned hyperextended at its IP and MCP limits stopped 2.4 mm
    /// short of its goal pressed 2 mm into a cylinder, and the grasp had no thumb).
    double jointMargin = 5 * 3.14159265358979323846 / 180;
    /// Power grasps: the object starts where the thesis's ball sits under the palm of the
    /// start pose (ball-clutch.yaml: centre p_GO at this point in G for the male reference
    /// subject, radius ballRadius), scaled with the hand length and moved palmar by the
    /// difference in radius. Otherwise the object starts where the goal pads' normals meet.
    bool startUnderPalm = false;
    double ballPosition[3] = {0.455, -0.169, -0.025};  ///< m, in G
    double ballRadius = 0.045;                         ///< m
};

/// The template of `type`: power-sphere and power-cylinder start from the thesis's ball-clutch
/// pose (models/scenarios/ball-clutch.yaml: shoulder flexion 30, elbow flexion 90, pronation 75,
/// wrist flexion 30 deg, palm down); pinch, tripod and lateral from its phone-pinch pose.
GraspTemplate findGraspTemplate(GraspType type);

/// True for joints the planner moves: the finger and thumb joints (prefix "thumb_", "index_",
/// "middle_", "ring_", "little_"); the arm and wrist keep the template's posture.
bool isFingerJoint(const std::string& joint);

}  // namespace graspsim::planning
