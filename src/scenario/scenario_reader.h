#pragma once
// Turns a parsed scenario document into a Scenario, checking every field. The first field that
// is not accepted throws InputError naming the file, the line, the field path and the value.

#include "yaml_field.h"

#include "graspsim/scenario/scenario.h"

namespace graspsim::scenario {

// Reads the whole document. The result's `source` is the root's source.
Scenario readScenario(const YamlField& root);

}  // namespace graspsim::scenario
