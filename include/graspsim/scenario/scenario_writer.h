#pragma once
/// @file
/// Writing a Scenario back as a scenario file: every field, defaults included, so a result folder
/// says exactly what ran (the "resolved" scenario).
///
/// The text is the format of scenario_file.h (angles in degrees, everything else SI) with numbers
/// written to 17 significant digits, so loadScenarioFile() reads it back to the same Scenario
/// (angles to the round-off of the degree conversion, about 1e-16 rad). Keys come in the order of
/// models/scenarios/ball-clutch.yaml, which documents them.

#include "graspsim/scenario/scenario.h"

#include <string>

namespace graspsim::scenario {

/// The YAML text of `scenario`, each key written out, `header` (may be empty) as leading
/// comment lines.
std::string formatScenarioYaml(const Scenario& scenario, const std::string& header = "");

}  // namespace graspsim::scenario
