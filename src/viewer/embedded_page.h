#pragma once
// The replay page's parts, compiled into the library by cmake/EmbedFiles.cmake: the template
// (page/replay.html), its script (page/replay.js), and three.js with OrbitControls from Debian's
// libjs-three, so the page is built without reading any file but the result's.

#include "graspsim/io/embedded_file.h"

#include <cstddef>
#include <string_view>

namespace graspsim::viewer {

using io::EmbeddedFile;

// Defined in the generated embedded_page_data.cpp.
extern const EmbeddedFile kEmbeddedFiles[];
extern const std::size_t kEmbeddedFileCount;

}  // namespace graspsim::viewer
