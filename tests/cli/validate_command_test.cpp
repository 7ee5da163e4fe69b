// Runs `graspsim validate`: bad names and unwritable folders are refused before any
// simulation; the quick suite passes its bounds and leaves the report, tables and plots.

#include "cli_process.h"

#include <gtest/gtest.h>

namespace fs = std::filesystem;
using graspsim::testing::RunResult;
using graspsim::testing::slurp;
using ValidateCommand = graspsim::testing::CliProcess;

TEST_F(ValidateCommand, RejectsUnknownNamesAndUnwritableFoldersBeforeSimulating) {
    const std::string out = " --out " + (dir_ / "v").string();
    for (const auto& [args, fragment] : {std::pair{"validate --experiment mug" + out, "--experiment: 'mug'"},
                                         std::pair{"validate --mode approx-glue" + out, "--mode: 'approx-glue'"},
                                         std::pair{"validate --long-hold -5" + out, "--long-hold"}}) {
        const RunResult r = run(args);
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_NE(r.err.find(fragment), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(dir_ / "v")) << args;
    }
    const std::string file = write("occupied", "a file where the folder should go");
    const RunResult r = run("validate --quick --out " + file + "/v");
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("--out"), std::string::npos) << r.err;
}

TEST_F(ValidateCommand, BenchRejectsADurationTooShortToEngage) {
    const RunResult r = run("bench --duration 1");
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("--duration: value 1"), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
}
