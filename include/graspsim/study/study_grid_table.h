#pragma once
/// @file
/// A study's results as a Markdown grid for people (results.md), next to results.csv: one
/// column per base scenario (the `base:` list, named by file stem), one row per combination of
/// the other axes except `mode`. A cell merges its cases:
///  - a failed case: its error (a grasp that cannot be planned, a set-up the check refuses);
///  - full mode (or no mode axis): "held" or "DROPPED" with the object's drift after settling
///    (object_displacement_m), the deepest segment overlap at t = 0 (initial_penetration_m) and
///    the planning time (plan_time_s, when the grasp was planned on load);
///  - approx mode: whether the approximation engaged.
/// Used by `graspsim study run` and `study collect` (docs/planning.md shows the grasp-types one).

#include "graspsim/study/study_spec.h"

#include <string>

namespace graspsim::study {

/// The grid's Markdown text, or "" when the study has no base list (nothing to put in columns).
/// @throws graspsim::InputError when a finished case's summary.json cannot be read.
std::string formatGridTable(const StudySpec& spec, const std::string& folder);

}  // namespace graspsim::study
