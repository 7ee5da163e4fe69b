#pragma once
// Reads the scenario's `object` section: its shape, the fields that shape needs (and no
// others), mass and initial pose; a mesh file is read and checked here (model/mesh_file.h).

#include "yaml_field.h"

#include "graspsim/scenario/scenario.h"

namespace graspsim::scenario {

// The object of the document `root`; a mesh path is taken relative to the scenario file.
// `planned` (the scenario gives grasp.type): the planner places the object, so a position or
// orientation is refused.
ObjectSpec readObject(const YamlField& root, bool planned);

}  // namespace graspsim::scenario
