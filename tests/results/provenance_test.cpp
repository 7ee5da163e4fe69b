// What a result says made it. Oracles: the Simbody version CMake's find_package found (the library
// loaded at run time must be that one), git for the commit, and the written JSON read back.

#include "graspsim/results/provenance.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <regex>

namespace graspsim::results {
namespace {

std::string runGit(const std::string& args) {
    std::string output;
    FILE* pipe = ::popen(("git -C " + std::string(GRASPSIM_SOURCE_DIR) + " " + args + " 2>/dev/null").c_str(), "r");
    if (!pipe) return output;
    char buffer[256];
    while (std::fgets(buffer, sizeof buffer, pipe)) output += buffer;
    ::pclose(pipe);
    while (!output.empty() && output.back() == '\n') output.pop_back();
    return output;
}

TEST(Provenance, NamesTheLibrariesLoaded) {
    const BuildProvenance build = findBuildProvenance();
    EXPECT_EQ(build.simbodyVersion.rfind(GRASPSIM_SIMBODY_VERSION, 0), 0u) << build.simbodyVersion << " vs " << GRASPSIM_SIMBODY_VERSION;
    EXPECT_TRUE(std::regex_match(build.sundialsVersion, std::regex(R"(\d+\.\d+\.\d+)"))) << build.sundialsVersion;
    EXPECT_TRUE(std::regex_match(build.version, std::regex(R"(\d+\.\d+\.\d+)"))) << build.version;
}

// The commit is HEAD's when the test binary was built from this checkout (it is rebuilt whenever
// the commit changes, as the build regenerates build_info.cpp).
TEST(Provenance, CommitIsTheCheckoutsHead) {
    const std::string head = runGit("rev-parse HEAD");
    if (head.empty()) GTEST_SKIP() << "not a git checkout";
    const std::string commit = findBuildProvenance().commit;
    EXPECT_EQ(commit.substr(0, 40), head);
    EXPECT_TRUE(commit.size() == 40 || commit == head + "-dirty") << commit;
}

TEST(Provenance, JsonAndVersionTextSayTheSame) {
    const BuildProvenance build = findBuildProvenance();
    const nlohmann::json j =
        nlohmann::json::parse(formatProvenanceJson(build, {{"graspsim", "simulate", "ball-clutch"}, {{"mode", "full"}}}));
    EXPECT_EQ(j["format"], kResultFormat);
    EXPECT_EQ(j["graspsim"]["version"], build.version);
    EXPECT_EQ(j["graspsim"]["commit"], build.commit);
    EXPECT_EQ(j["libraries"]["simbody"], build.simbodyVersion);
    EXPECT_EQ(j["libraries"]["sundials"], build.sundialsVersion);
    EXPECT_EQ(j["command_line"], nlohmann::json::array({"graspsim", "simulate", "ball-clutch"}));
    EXPECT_EQ(j["run"]["mode"], "full");
    const std::string text = formatVersionText(build);
    for (const std::string& part : {build.version, build.commit, build.simbodyVersion, build.sundialsVersion}) {
        EXPECT_NE(text.find(part), std::string::npos) << part;
    }
}

}  // namespace
}  // namespace graspsim::results
