#pragma once
// The single output file of `model build`, `model object` and `grasp plan` (-o), checked before
// any work: a folder or a path in a folder that does not exist would otherwise be found only when
// the file is written, after the model is built or the grasp planned, and named without -o.

#include <string>

namespace graspsim::cli {

// Throws InputError "<option>: value '<path>' is ..." when `path` is an existing folder, ends in
// a separator, or lies in a folder that does not exist. Whether the folder can be written is left
// to the atomic write, which says so with the system's reason.
void checkOutputFile(const std::string& path, const std::string& option);

}  // namespace graspsim::cli
