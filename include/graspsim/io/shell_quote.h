#pragma once
/// @file
/// Quoting a word for /bin/sh, for the command lines graspsim hands to a shell (the plot
/// interpreter, sbatch).

#include <string>

namespace graspsim::io {

/// `text` single-quoted for /bin/sh, so that the shell passes it on as one word unchanged:
/// every ' becomes '\'' (close the quote, an escaped quote, reopen).
std::string quoteForShell(const std::string& text);

}  // namespace graspsim::io
