#pragma once
/// @file
/// The files a simulation run leaves in its output folder.
///
/// - trajectory.csv: time (s), object position x, y, z (m, ground), orientation quaternion
///   w, x, y, z, grasp quality (N, smallest singular value of the grasp matrix), then every hand
///   joint angle (rad) by name;
/// - contacts.csv: one row per contact and output time: time (s), body_a, shape_a, body_b,
///   shape_b, contact point x, y, z (m, ground), normal x, y, z (from a toward b), normal force
///   (N), friction force on b x, y, z (N, ground), penetration (m). For a hand-object contact a is
///   the hand segment and its capsule (e.g. index_distal, index_distal_capsule) and b the object:
///   body "object" in every scenario, shape the scenario's object shape ("box", "sphere", "mesh", ...);
/// - summary.json: the SimulationSummary fields (see grasp_simulation.h), with "complete": false
///   and "failure" when the run stopped early; approx runs add engaged, engage_time_s and
///   release_time_s (null when none), q_at_engage_n, q_threshold_n and approx_step_us;
/// - events.csv (approx runs only): time (s), event (engage or release), grasp quality (N), and
///   the reason in double quotes;
/// - constraint.csv (approx runs only): one row per output time while the merged approximation is
///   engaged (simulation/constraint_sample.h): time (s), the constraint frame M's origin x, y, z (m,
///   ground) and orientation quaternion w, x, y, z, then per axis rx, ry, rz, x, y, z its limit
///   (N m, N; "inf" on a locked axis; the upper side of two-sided limits), its reaction on the
///   object (N m, N, along M's axes), and its lower limit (the reaction stays >= -lower_limit;
///   equal to the limit for symmetric limits).
/// Each file is written whole to a temporary name and renamed, so a crash never leaves half a file.

#include "graspsim/simulation/grasp_simulation.h"

#include <string>

namespace graspsim::results {

/// trajectory.csv's text.
std::string formatTrajectoryCsv(const simulation::SimulationResult& result);
/// contacts.csv's text.
std::string formatContactsCsv(const simulation::SimulationResult& result);
/// summary.json's text.
std::string formatSummaryJson(const simulation::SimulationSummary& summary);

/// events.csv's text.
std::string formatEventsCsv(const simulation::SimulationResult& result);

/// constraint.csv's text.
std::string formatConstraintCsv(const simulation::SimulationResult& result);

/// Writes the three files (five in approx mode) into `folder`, which must exist.
/// @throws graspsim::InputError naming the file when it cannot be written.
void writeResultFiles(const std::string& folder, const simulation::SimulationResult& result);

}  // namespace graspsim::results
