#pragma once
// Declarations for the generated embedded_capacity_scripts_data.cpp (cmake/EmbedFiles.cmake).
#include "graspsim/io/embedded_file.h"

namespace graspsim::capacity {
using io::EmbeddedFile;
extern const EmbeddedFile kEmbeddedFiles[];
extern const std::size_t kEmbeddedFileCount;
}  // namespace graspsim::capacity
