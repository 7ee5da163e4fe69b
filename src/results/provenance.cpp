#include "graspsim/results/provenance.h"

#include <nlohmann/json.hpp>
#include <simbody/Simbody.h>
#include <sundials/sundials_config.h>

namespace graspsim::results {

namespace build {
// Defined in the build_info.cpp that cmake/BuildInfo.cmake generates at every build.
extern const char* const kVersion;
extern const char* const kCommit;
}  // namespace build

BuildProvenance findBuildProvenance() {
    BuildProvenance provenance;
    provenance.version = build::kVersion;
    provenance.commit = build::kCommit;
    // Simbody is a shared library: ask the one actually loaded, not the headers compiled against.
    int major = 0, minor = 0, patch = 0;
    SimTK_version_simbody(&major, &minor, &patch);
    provenance.simbodyVersion = std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(patch);
    // SUNDIALS is linked statically (src/integration/CMakeLists.txt): its headers' version is the code's.
    provenance.sundialsVersion = SUNDIALS_VERSION;
    return provenance;
}

std::string formatVersionText(const BuildProvenance& build) {
    return "graspsim " + build.version + "\ncommit " + build.commit + "\nSimbody " + build.simbodyVersion +
           "\nSUNDIALS " + build.sundialsVersion + "\n";
}

std::string formatProvenanceJson(const BuildProvenance& build, const RunProvenance& run) {
    nlohmann::ordered_json j;
    j["format"] = kResultFormat;
    j["graspsim"] = {{"version", build.version}, {"commit", build.commit}};
    j["libraries"] = {{"simbody", build.simbodyVersion}, {"sundials", build.sundialsVersion}};
    j["command_line"] = run.commandLine;
    nlohmann::ordered_json options = nlohmann::ordered_json::object();
    for (const auto& [name, value] : run.run) options[name] = value;
    j["run"] = options;
    return j.dump(2) + "\n";
}

}  // namespace graspsim::results
