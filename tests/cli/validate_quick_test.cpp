// The quick validation suite end to end (ctest label `validation`): full contact and the
// approximation of ball-clutch, their comparison against the validation bounds, and the files.

#include "cli_process.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

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
                             "ball-clutch_error.png", "capacity_ball-clutch.png"}) {
        EXPECT_GT(fs::file_size(out / plot), 1000u) << plot;
        EXPECT_NE(report.find(plot), std::string::npos) << plot;
    }
    EXPECT_TRUE(fs::exists(out / "runs" / "ball-clutch_none_full" / "trajectory.csv"));
    // The capacity comparison, quick: the -y pull on full contact and on the default approximation,
    // whose slip onsets agree within 10 % (the bound).
    std::istringstream capacity(slurp(out / "capacity.csv"));
    std::string line;
    std::vector<std::string> rows;
    while (std::getline(capacity, line)) rows.push_back(line);
    ASSERT_EQ(rows.size(), 3u) << slurp(out / "capacity.csv");
    EXPECT_EQ(rows[1].rfind("ball-clutch,-y,full,N,", 0), 0u) << rows[1];
    EXPECT_EQ(rows[2].rfind("ball-clutch,-y,approx-bushing-merged,N,", 0), 0u) << rows[2];
    const std::vector<std::string> fields = [&] {
        std::vector<std::string> f;
        std::istringstream in(rows[2]);
        for (std::string cell; std::getline(in, cell, ',');) f.push_back(cell);
        return f;
    }();
    ASSERT_GT(fields.size(), 14u);
    // The default approximation hands the object back by the compliance model (its limits, or its
    // creep watch, which comes first here: 11.28 N), before full contact's slip onset (full
    // contact's ramp is the oracle), and the hand-back does not let go of what full contact holds:
    // its onset is not more than 10 % below full contact's (the bound). How far above it
    // comes (+2.1 % at this rate) is a finding of the report's table (docs/capacity.md), not a check.
    ASSERT_EQ(fields[5], "1") << rows[2];
    ASSERT_EQ(fields[10], "1") << rows[2];  // released
    EXPECT_NE(fields[13].find("compliance"), std::string::npos) << rows[2];
    const double fullOnset = std::stod([&] {
        std::istringstream in(rows[1]);
        std::string cell;
        for (int k = 0; k <= 6; ++k) std::getline(in, cell, ',');
        return cell;
    }());
    EXPECT_LT(std::stod(fields[11]), fullOnset) << rows[2];  // release_load
    EXPECT_GT(std::stod(fields[12]), -0.10) << rows[2];      // relative_difference_to_full
    EXPECT_NE(report.find("## Holding capacity"), std::string::npos);
    // The constant load at 1.25 x full contact's ramp onset slips on both (the overload_* columns),
    // and report.md has its table. Full contact's grip at the load's start carries the ball's weight
    // (1.962 N, half the default rate) by friction of at most mu_s = 0.9 times it: >= 2.18 N. The
    // engaged approximation's is not measured (empty).
    const auto split = [](const std::string& text) {
        std::vector<std::string> f;
        std::istringstream in(text + ",");  // a last empty cell is read too
        for (std::string cell; std::getline(in, cell, ',');) f.push_back(cell);
        return f;
    };
    const std::vector<std::string> header = split(rows[0]);
    const auto column = [&](const std::string& name) {
        return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
    };
    for (const std::size_t row : {1u, 2u}) {
        const std::vector<std::string> f = split(rows[row]);
        ASSERT_EQ(f.size(), header.size()) << rows[row];
        EXPECT_EQ(f[column("overload_slipped")], "1") << rows[row];
        EXPECT_GT(std::stod(f[column("overload_slip_onset_time_s")]), 0) << rows[row];
    }
    EXPECT_GT(std::stod(split(rows[1])[column("grip_force_start_n")]), 1.962 / 0.9) << rows[1];
    EXPECT_EQ(split(rows[2])[column("grip_force_start_n")], "") << rows[2];
    EXPECT_NE(report.find("### Slip-onset times under a constant load above capacity"), std::string::npos);
    // The polar plot's data: each variant's ramps in capacity.json, as `graspsim capacity` writes them.
    EXPECT_NE(slurp(out / "capacity" / "ball-clutch" / "approx-bushing-merged" / "capacity.json").find("\"slip_onset_n\""),
              std::string::npos);
}
