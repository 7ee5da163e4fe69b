#pragma once
/// @file
/// The validation suite's files for people and for scripts.
///
/// - results.csv: one row per run: id, scenario, perturbation, contact, variant, complete, held,
///   reference_held, object_displacement_m, reference_displacement_m, slip_onset_s,
///   reference_slip_onset_s (-1 = no slip), engage_time_s and release_time_s (-1 = none),
///   q_at_engage_n, max_penetration_m, max/rms position error (m) and max/rms orientation error
///   (rad) against the reference from engagement to the end (empty without a reference), the
///   same max errors over the 2 s after engagement, wall_time_s, sim_time_s, steps,
///   full_wall_per_sim_s, approx_wall_per_sim_s;
/// - checks.csv: run, check, value, relation, bound, unit, pass (1/0), source;
/// - report.md: a summary line, the checks table with pass/fail, and the per-run table.

#include "graspsim/validation/validation_suite.h"

#include <string>

namespace graspsim::validation {

std::string formatResultsCsv(const ValidationResults& results);
std::string formatChecksCsv(const ValidationResults& results);
/// `plots`: PNG file names (relative to the report) to embed, in order.
std::string formatReportMarkdown(const ValidationResults& results, const std::vector<std::string>& plots);

/// Writes results.csv, checks.csv and report.md into `folder` (whole files, temp + rename).
/// @throws graspsim::InputError naming the file when it cannot be written.
void writeValidationReport(const std::string& folder, const ValidationResults& results,
                           const std::vector<std::string>& plots);

}  // namespace graspsim::validation
