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

/// The planned scenario's YAML (scenario_writer.h), headed by comment lines that say it was
/// planned, for which request, and the plan's checks (pad gaps in mm, deepest segment, Q).
std::string formatPlannedScenario(const scenario::Scenario& planned, const GraspPlan& plan);

}  // namespace graspsim::planning
