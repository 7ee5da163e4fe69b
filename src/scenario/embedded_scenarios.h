#pragma once
// The built-in scenario files (models/scenarios/*.yaml), compiled into the library by
// cmake/EmbedFiles.cmake so that the binary never reads the source tree.

#include <cstddef>
#include <string_view>

namespace graspsim::scenario {

struct EmbeddedFile {
    std::string_view name;  // file name without directory, e.g. "ball-clutch.yaml"
    std::string_view text;  // the whole file
};

// Defined in the generated embedded_scenarios_data.cpp.
extern const EmbeddedFile kEmbeddedFiles[];
extern const std::size_t kEmbeddedFileCount;

}  // namespace graspsim::scenario
