#pragma once
/// @file
/// The one entry point from a subject and options to a model description.

#include "graspsim/model/build_options.h"
#include "graspsim/model/model_description.h"

namespace graspsim::model {

/// Builds the body chosen in `options` (arm or humanoid) for its subject, applies the preset,
/// and validates the result.
/// @throws graspsim::InputError when the options are out of range.
ModelDescription buildBodyModel(const BuildOptions& options);

}  // namespace graspsim::model
