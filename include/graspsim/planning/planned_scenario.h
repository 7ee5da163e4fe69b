#pragma once
/// @file
/// Planned grasps as scenarios: a scenario whose grasp pose, goals and object placement come
/// from planGrasp(), for `graspsim grasp plan` and for scenario files that ask for a grasp type
/// instead of giving a pose.

#include "graspsim/planning/grasp_planner.h"
#include "graspsim/scenario/scenario.h"

#include <string>

namespace graspsim::planning {

/// `base` with the plan's grasp pose, goals, object position and orientation and the grasp
/// type's controller gain filled in. Everything else (subject, object shape and mass, contact,
/// simulation) is kept from `base`.
scenario::Scenario applyPlan(const scenario::Scenario& base, const GraspPlan& plan);

/// Plans `type` for the subject and object of `base` and applies the plan.
/// @throws NoGraspError or InputError as planGrasp.
scenario::Scenario planScenario(const scenario::Scenario& base, GraspType type);

/// Plans `scenario` when it asks for a grasp type (`grasp: {type: ...}`, Scenario::graspType):
/// fills in its grasp pose, goals and object placement and clears graspType; its controller
/// settings stay as the file gives them (kp default 5; `grasp plan` writes 10 for power grasps,
/// as ball-clutch.yaml). A scenario that
/// gives its pose is left as it is.
/// @throws InputError naming the file and field for an unknown grasp type; NoGraspError.
void completeScenario(scenario::Scenario& scenario);

/// scenario::loadScenario(nameOrPath), then completeScenario(): what the command line runs.
scenario::Scenario loadScenario(const std::string& nameOrPath);

/// The planned scenario's YAML (scenario_writer.h), headed by comment lines that say it was
/// planned, for which request, and the plan's checks (pad gaps in mm, deepest segment, Q; for two
/// contacts, whose Q is round-off, the antipodal test).
std::string formatPlannedScenario(const scenario::Scenario& planned, const GraspPlan& plan);

}  // namespace graspsim::planning
