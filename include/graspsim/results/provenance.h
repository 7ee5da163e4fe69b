#pragma once
/// @file
/// What made a result: graspsim's version and commit, the libraries it ran on, the command line,
/// written as provenance.json into every result folder (beside scenario.yaml and model.urdf).
///
/// provenance.json:
///   {"format": kResultFormat, "graspsim": {"version", "commit"}, "libraries": {"simbody",
///    "sundials"}, "command_line": [argv...], "run": {option: value, ...}}
/// "commit" is the git commit the binary was built from ("-dirty" appended when tracked files had
/// uncommitted changes; "unknown" outside a git checkout). "run" holds the per-run choices that
/// are not part of the scenario (contact model, mode, perturbation, integrator, ...).

#include <map>
#include <string>
#include <vector>

namespace graspsim::results {

/// Version of the result folder's layout; a reader (e.g. the viewer) refuses other versions.
/// 1: trajectory.csv, contacts.csv, summary.json, events.csv and constraint.csv (approx),
/// scenario.yaml, model.urdf, provenance.json.
constexpr int kResultFormat = 1;

/// The build and the libraries it runs on.
struct BuildProvenance {
    std::string version;          ///< graspsim's version, e.g. "0.1.0"
    std::string commit;           ///< git commit of the build (see the file comment)
    std::string simbodyVersion;   ///< the Simbody library loaded at run time, "major.minor.build"
    std::string sundialsVersion;  ///< the SUNDIALS linked in (statically), e.g. "6.4.1"
};

/// This binary's BuildProvenance.
BuildProvenance findBuildProvenance();

/// The text `graspsim --version` prints: version, commit and library versions, one per line.
std::string formatVersionText(const BuildProvenance& build);

/// One run's provenance.
struct RunProvenance {
    std::vector<std::string> commandLine;     ///< argv as given
    std::map<std::string, std::string> run;  ///< per-run choices, by option name
};

/// provenance.json's text.
std::string formatProvenanceJson(const BuildProvenance& build, const RunProvenance& run);

}  // namespace graspsim::results
