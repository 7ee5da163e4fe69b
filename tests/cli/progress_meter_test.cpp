// The progress display: time left at the pace so far (worked by hand), its formatting, and silence
// when stderr is not a terminal or with --quiet (the CLI tests run `graspsim` with stderr in a file
// and check it holds one line on bad input, so a stray progress line would also fail them).

#include "progress_meter.h"

#include <gtest/gtest.h>

#include <unistd.h>

namespace graspsim::cli {
namespace {

TEST(ProgressMeter, EstimatesTheTimeLeftAtThePaceSoFar) {
    // 30 s for 1 of 4 units: 3 units left at 30 s each.
    EXPECT_DOUBLE_EQ(ProgressMeter::estimateTimeLeft(30, 1, 4), 90);
    EXPECT_DOUBLE_EQ(ProgressMeter::estimateTimeLeft(12, 0.6, 3.0), 48);
    EXPECT_DOUBLE_EQ(ProgressMeter::estimateTimeLeft(5, 4, 4), 0);
    EXPECT_LT(ProgressMeter::estimateTimeLeft(5, 0, 4), 0) << "no pace before anything is done";
}

TEST(ProgressMeter, FormatsDurationsToTheSecond) {
    EXPECT_EQ(ProgressMeter::formatDuration(0.4), "0s");
    EXPECT_EQ(ProgressMeter::formatDuration(42.4), "42s");
    EXPECT_EQ(ProgressMeter::formatDuration(185), "3m05s");
    EXPECT_EQ(ProgressMeter::formatDuration(3725), "1h02m");
}

TEST(ProgressMeter, ShownOnlyOnATerminalAndNotWhenQuiet) {
    EXPECT_FALSE(ProgressMeter("test", true).isShown());
    EXPECT_EQ(ProgressMeter("test", false).isShown(), ::isatty(STDERR_FILENO) == 1);
}

}  // namespace
}  // namespace graspsim::cli
