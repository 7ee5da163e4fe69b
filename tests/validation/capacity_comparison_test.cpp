#include "graspsim/validation/capacity_comparison.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace graspsim::validation {
namespace {

CapacityRow makeRow(const std::string& experiment, const std::string& load, const std::string& variant, double slip) {
    CapacityRow row;
    row.experiment = experiment;
    row.load = load;
    row.variant = variant;
    row.measured.trace.figures.slipped = slip > 0;
    row.measured.trace.figures.slipOnsetLoad = slip;
    return row;
}

// One table per experiment, one line per load, one column per variant, in run order.
TEST(CapacityComparison, ReportTablesHaveALinePerLoadAndAColumnPerVariant) {
    std::vector<CapacityRow> rows;
    for (const char* experiment : {"ball-clutch", "phone-pinch"}) {
        for (const char* load : {"-y", "x"}) {
            rows.push_back(makeRow(experiment, load, "full", 10));
            rows.push_back(makeRow(experiment, load, "approx-bushing-merged", 11));
            rows.back().hasReference = true;
            rows.back().relativeDifference = 0.1;
        }
    }
    const std::string md = formatCapacityMarkdown(rows);
    EXPECT_NE(md.find("### ball-clutch\n\n| load | full | approx-bushing-merged |\n|---|---|---|\n| -y | 10 N | 11 N (+10 %) |\n"
                      "| x | 10 N | 11 N (+10 %) |\n"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("### phone-pinch"), std::string::npos);
    const std::string csv = formatCapacityCsv(rows);
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 9);
    EXPECT_TRUE(formatCapacityMarkdown({}).empty());
}

}  // namespace
}  // namespace graspsim::validation
