#pragma once
// Options that only the grasp approximation reads (--constraint, --limits, --q-minimum, ...):
// given without --mode approx they would be silently unused, and the run would not be the one
// asked for.

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace graspsim::cli {

// Throws InputError "<option>: value '<v>' is not accepted with --mode <mode>; ..." for the first
// of `names` given on `command` when `mode` is not "approx".
void checkApproxOnlyOptions(const CLI::App& command, const std::string& mode, const std::vector<std::string>& names);

}  // namespace graspsim::cli
