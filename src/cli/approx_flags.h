#pragma once
// The grasp approximation's flags that `simulate` and `capacity` share (--constraint, --attach,
// --q-minimum, --limits, --release-at, --release-give, --hand-back, --bushing-give): defined and
// read in one place, so that both commands offer them with the same defaults, words and checks.
// Given without --mode approx they would be silently unused, and the run would not be the one
// asked for: checkApproxOnlyOptions refuses them.

#include "graspsim/simulation/simulation_options.h"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace graspsim::cli {

// The shared flags as given, with their defaults.
struct ApproxFlags {
    std::string constraint = "bushing";
    std::string attach = "merged";
    std::string qMinimum;
    std::string limits = "thesis";
    std::string releaseAt = "auto";
    std::string releaseGive;
    std::string handBack = "engaged";
    std::string releaseCreep;
    std::string bushingGive = "auto";
};

// Adds the shared flags to `command`, bound to `flags` (which must outlive the parse).
void addApproxFlags(CLI::App& command, ApproxFlags& flags);

// The names of the shared flags, for checkApproxOnlyOptions.
std::vector<std::string> getApproxFlagNames();

// Writes the shared flags into `options` (the fields they set; the others are left).
// Throws InputError naming the flag and value for one that is not accepted.
void parseApproxFlags(const ApproxFlags& flags, simulation::ApproxOptions& options);

// Throws InputError "<option>: value '<v>' is not accepted with --mode <mode>; ..." for the first
// of `names` given on `command` when `mode` is not "approx".
void checkApproxOnlyOptions(const CLI::App& command, const std::string& mode, const std::vector<std::string>& names);

}  // namespace graspsim::cli
