#pragma once
/// @file
/// The set-up check: whether a scenario's grasp can start at all, decided at t = 0 before any
/// integration and before anything is written.
///
/// At t = 0 the grasp pose is applied kinematically and the object sits at its initial pose
/// (GraspScene::makeInitialState). Two things make a run meaningless from there, and both used to
/// pass silently (a subject the hand-found pose was not made for):
///  - a hand or arm segment already inside the object: contact then starts with a force far
///    beyond any grasp force and throws the object away. Measured with contact::findContacts
///    between each segment geometry and each object geometry (the deepest contact of each pair);
///    more than kMaxInitialPenetration is refused.
///  - a goal the fingertip cannot reach: the controller's IK (a least-squares fit within the
///    joints' ranges of motion, fingertip_ik.h), solved from the grasp pose for the goals moved
///    press_depth inside the surface, leaves the end-effector short of its goal. More than
///    kGoalReachTolerance is refused.

#include "graspsim/scenario/scenario.h"
#include "graspsim/simulation/simulation_options.h"

#include "graspsim/simbody.h"

#include <string>
#include <vector>

namespace graspsim::simulation {

class GraspScene;

/// Deepest overlap a segment may have with the object at t = 0 (m). The limit of the issue that
/// asked for the check; it is half the 2 mm press depth of the built-in scenarios, so a refused
/// segment starts deeper than the fingertips are ever meant to press.
constexpr double kMaxInitialPenetration = 1e-3;

/// Largest distance between a goal end-effector and its (pressed-in) goal after the t = 0 IK
/// solution (m). A reachable goal is met to the Assembler's accuracy (1e-6 m); a joint at its
/// range-of-motion limit leaves a gap that grows with how far the goal is out of reach. 3 mm is
/// above the 2 mm press depth: a fingertip that far short of its goal along the normal would not
/// touch the object at all, and sideways it is two fifths of the 7.5 mm fingertip pad radius,
/// so the pad would still press the object near the goal.
constexpr double kGoalReachTolerance = 3e-3;

/// The deepest overlap of one segment geometry with the object.
struct SegmentOverlap {
    std::string body;      ///< model body name (e.g. "index_distal")
    std::string geometry;  ///< the body's geometry name
    double depth = 0;      ///< deepest contact depth (m), > 0
};

/// How close the t = 0 IK brings one goal's end-effector to its goal.
struct GoalReach {
    std::string endEffector;  ///< e.g. "index_tip"
    double distance = 0;      ///< end-effector to the goal pressed press_depth inside the surface (m)
};

/// What the check measured at t = 0.
struct SetupCheck {
    /// Deepest segment-object overlap (m); 0 if no segment touches the object.
    double initialPenetration = 0;
    /// Every overlapping segment geometry, deepest first.
    std::vector<SegmentOverlap> overlaps;
    /// Every goal, in the scenario's goal order.
    std::vector<GoalReach> goals;
};

/// Measures `state`, the scene's initial state (GraspScene::makeInitialState: grasp pose applied,
/// object placed, the controller's first IK solved). Realizes `state` to Stage::Position.
/// @throws graspsim::InputError when an object geometry has no contact support.
SetupCheck calcSetupCheck(const GraspScene& scene, const SimTK::State& state);

/// Throws when `check` fails: one line naming the deepest segment and its depth, or the farthest
/// goal and its distance, with the limit, after `where` (the scenario's file, or its name).
/// @throws graspsim::InputError (exit code 2 in the CLI).
void requireSetup(const SetupCheck& check, const std::string& where);

/// Builds the scenario's run with `options` (GraspExperiment: scene, approximation, loads), makes
/// its initial state and checks it: what a command calls before it writes anything. Returns what
/// was measured.
/// @throws graspsim::InputError as requireSetup, or for options the run rejects.
SetupCheck checkScenarioSetup(const scenario::Scenario& scenario, const SimulationOptions& options);

}  // namespace graspsim::simulation
