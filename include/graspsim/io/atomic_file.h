#pragma once
/// @file
/// Writing output files so that a failure never leaves a half-written file behind.

#include <string>

namespace graspsim::io {

/// Writes `contents` to `path` through a temporary file in the same folder, renamed over
/// `path` only once everything was written and flushed. On any failure the temporary file
/// is removed and `path` is left as it was.
/// @throws graspsim::InputError naming the path when the folder cannot be written.
void writeFileAtomically(const std::string& path, const std::string& contents);

/// Removes `path`, an output an earlier run left in a reused folder that this run does not write
/// (so that the folder's files all come from one run); a missing file is fine.
/// @throws graspsim::InputError naming the path when it exists and cannot be removed.
void removeStaleFile(const std::string& path);

/// Reads a whole text file.
/// @throws graspsim::InputError naming the path when it cannot be read.
std::string readTextFile(const std::string& path);

}  // namespace graspsim::io
