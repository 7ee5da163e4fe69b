#pragma once
// The built-in scenario files (models/scenarios/*.yaml), compiled into the library by
// cmake/EmbedFiles.cmake so that the binary never reads the source tree.

#include "graspsim/io/embedded_file.h"

#include <cstddef>
#include <string_view>

namespace graspsim::scenario {

using io::EmbeddedFile;

// Defined in the generated embedded_scenarios_data.cpp.
extern const EmbeddedFile kEmbeddedFiles[];
extern const std::size_t kEmbeddedFileCount;

}  // namespace graspsim::scenario
