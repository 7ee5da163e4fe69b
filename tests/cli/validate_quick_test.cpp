// The quick validation suite end to end (ctest label `validation`): full contact and the
// approximation of ball-clutch, their comparison against the validation bounds, and the files.

#include "cli_process.h"

#include <gtest/gtest.h>

namespace fs = std::filesystem;
using graspsim::testing::RunResult;
using graspsim::testing::slurp;
using ValidateQuick = graspsim::testing::CliProcess;

TEST_F(ValidateQuick, PassesEveryBoundAndWritesReportTablesAndPlots) {
    const fs::path out = dir_ / "validation";
    const RunResult r = run("validate --quick --out " + out.string());
    EXPECT_EQ(r.exitCode, 0) << r.out << r.err << slurp(out / "report.md");
    const std::string report = slurp(out / "report.md");
    EXPECT_NE(report.find(" 0 failed"), std::string::npos) << report;
    EXPECT_EQ(report.find("FAIL"), std::string::npos) << report;
    const std::string results = slurp(out / "results.csv");
    // header + full contact + its CVODE reference + bushing-merged, weld-merged, bushing-multi
    EXPECT_EQ(std::count(results.begin(), results.end(), '\n'), 6) << results;
    for (const char* plot : {"ball-clutch_trajectory.png", "ball-clutch_quality.png", "ball-clutch_forces.png",
                             "ball-clutch_error.png"}) {
        EXPECT_GT(fs::file_size(out / plot), 1000u) << plot;
        EXPECT_NE(report.find(plot), std::string::npos) << plot;
    }
    EXPECT_TRUE(fs::exists(out / "runs" / "ball-clutch_none_full" / "trajectory.csv"));
}
