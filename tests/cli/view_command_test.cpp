// `graspsim view`: writes replay.html into a result folder; bad input (not a result, an older
// result, a picture time outside the run, a bad size) gets one line, exit code 2, and nothing
// written. `--version` names the commit and the libraries, as provenance.json does.

#include "cli_process.h"

#include <gtest/gtest.h>

namespace fs = std::filesystem;
using graspsim::testing::RunResult;
using graspsim::testing::slurp;

namespace {

class ViewCommand : public graspsim::testing::CliProcess {
protected:
    // A 0.05-s full-contact phone run, in dir_/run.
    fs::path simulateShortRun() {
        const fs::path out = dir_ / "run";
        const RunResult r = run("simulate phone-pinch --duration 0.05 --out " + out.string());
        EXPECT_EQ(r.exitCode, 0) << r.err;
        extraFiles_ = 1;
        return out;
    }
    void expectRejected(const std::string& args, const fs::path& folder, const std::string& fragment) {
        const RunResult r = run(args);
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_NE(r.err.find(fragment), std::string::npos) << "missing '" << fragment << "' in: " << r.err;
        EXPECT_FALSE(fs::exists(folder / "replay.html")) << args;
        EXPECT_FALSE(fs::exists(folder / "replay.png")) << args;
    }
};

TEST_F(ViewCommand, WritesTheReplayIntoTheResultFolder) {
    const fs::path out = simulateShortRun();
    for (const char* file : {"scenario.yaml", "model.urdf", "provenance.json"}) EXPECT_TRUE(fs::exists(out / file)) << file;
    const RunResult r = run("view " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::string page = slurp(out / "replay.html");
    EXPECT_NE(page.find("GRASPSIM_REPLAY = {"), std::string::npos);
    EXPECT_NE(r.out.find("replay.html"), std::string::npos) << r.out;
}

TEST_F(ViewCommand, RefusesFoldersThatAreNotResults) {
    const fs::path out = simulateShortRun();
    expectRejected("view " + (dir_ / "missing").string(), dir_ / "missing", "is not a folder");
    fs::create_directories(dir_ / "other");
    std::ofstream(dir_ / "other" / "notes.txt") << "hello\n";
    expectRejected("view " + (dir_ / "other").string(), dir_ / "other", "is not a graspsim result folder");
    fs::remove(out / "provenance.json");  // as a result written before provenance existed
    expectRejected("view " + out.string(), out, "older graspsim");
}

TEST_F(ViewCommand, RefusesAPictureTimeOutsideTheRunOrABadSize) {
    const fs::path out = simulateShortRun();
    expectRejected("view " + out.string() + " --png 5", out, "--png: time 5 s is outside the run");
    expectRejected("view " + out.string() + " --png -0.1", out, "outside the run");
    expectRejected("view " + out.string() + " --png soon", out, "--png: value 'soon' is not a number");
    expectRejected("view " + out.string() + " --png 0.01 --size 10x10", out, "--size: value '10x10'");
    expectRejected("view " + out.string() + " --png 0.01 --size 1200x800x3", out, "--size: value '1200x800x3' is not accepted");
}

// --png-file alone would be silently unused; a folder, or a file in a folder that does not exist,
// would be found only after the replay is written and the picture rendered.
TEST_F(ViewCommand, RefusesAPictureFileWithoutATimeOrThatIsAFolder) {
    const fs::path out = simulateShortRun();
    expectRejected("view " + out.string() + " --png-file " + (dir_ / "p.png").string(), out,
                   "--png-file: value '" + (dir_ / "p.png").string() + "' is not accepted without --png TIME");
    EXPECT_FALSE(fs::exists(dir_ / "p.png"));
    expectRejected("view " + out.string() + " --png 0.01 --png-file " + dir_.string(), out,
                   "--png-file: value '" + dir_.string() + "' is a folder");
    expectRejected("view " + out.string() + " --png 0.01 --png-file " + (dir_ / "p.jpg").string(), out,
                   "--png-file: value '" + (dir_ / "p.jpg").string() + "' is not accepted; the picture is a PNG");
    expectRejected("view " + out.string() + " --size 800x600", out, "--size: value '800x600' is not accepted without --png TIME");
    const fs::path missing = dir_ / "no-such-folder" / "p.png";
    expectRejected("view " + out.string() + " --png 0.01 --png-file " + missing.string(), out,
                   "--png-file: value '" + missing.string() + "': folder '" + (dir_ / "no-such-folder").string() + "' does not exist");
}

TEST_F(ViewCommand, VersionNamesCommitAndLibraries) {
    const RunResult r = run("--version");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    for (const char* part : {"graspsim 0.", "commit ", "Simbody 3.", "SUNDIALS "}) EXPECT_NE(r.out.find(part), std::string::npos) << r.out;
}

}  // namespace
