// The report files: one CSV row per run and per check, failures marked in the Markdown.

#include "graspsim/validation/validation_report.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace graspsim;

TEST(ValidationReport, RowsPerRunAndCheckAndFailuresMarked) {
    validation::ValidationResults results;
    results.runs.resize(2);
    results.runs[0].run.id = "a_full";
    results.runs[1].run.id = "a_approx";
    results.runs[1].hasReference = true;
    results.checks.push_back({"a_full", "drift after settling", 0.3, 5, "mm", "<=", true, "a held object stays put"});
    results.checks.push_back({"a_approx", "position error", 2.5, 2, "mm", "<=", false, "thesis 5.1"});
    EXPECT_FALSE(results.passed());
    const auto lines = [](const std::string& s) { return std::count(s.begin(), s.end(), '\n'); };
    EXPECT_EQ(lines(validation::formatResultsCsv(results)), 3);
    EXPECT_EQ(lines(validation::formatChecksCsv(results)), 3);
    const std::string md = validation::formatReportMarkdown(results, {"x.png"});
    EXPECT_NE(md.find("2 checks, 1 failed"), std::string::npos) << md;
    EXPECT_NE(md.find("**FAIL**"), std::string::npos);
    EXPECT_NE(md.find("![x.png](x.png)"), std::string::npos);
}
