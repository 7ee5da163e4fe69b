#pragma once
/// @file
/// Text files compiled into a library by cmake/EmbedFiles.cmake (data tables, built-in
/// scenarios), so that the files in the source tree stay the single source of truth and no
/// binary reads the source tree at run time.

#include <cstddef>
#include <string>
#include <string_view>

namespace graspsim::io {

/// One embedded file.
struct EmbeddedFile {
    std::string_view name;  ///< file name without directory, e.g. "joint_ranges.csv"
    std::string_view text;  ///< the whole file
};

/// The text of the file called `name` among `count` embedded `files`.
/// @throws graspsim::Error listing what is embedded: a missing file is a build mistake.
std::string_view findEmbeddedFile(const EmbeddedFile* files, std::size_t count, const std::string& name);

}  // namespace graspsim::io
