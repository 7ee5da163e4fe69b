// SilencedStdout: what Simbody's debug trace writes (C printf and std::cout) goes nowhere while
// the guard lives, and both streams work again afterwards.
#include "graspsim/system/silenced_stdout.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <iostream>

namespace graspsim::system {
namespace {

TEST(SilencedStdout, PrintfFailsBeforeFormattingAndCoutIsANoOp) {
    std::FILE* const before = stdout;
    {
        const SilencedStdout quiet;
        // C11 7.21.2: a byte output function on a wide-oriented stream fails.
        EXPECT_LT(std::printf("%g\n", 1.0), 0);
        EXPECT_TRUE(std::cout.bad());
        {
            const SilencedStdout nested;
            EXPECT_LT(std::printf("%g\n", 2.0), 0);
        }
        EXPECT_LT(std::printf("%g\n", 3.0), 0);
    }
    EXPECT_EQ(stdout, before);
    EXPECT_FALSE(std::cout.bad());
    EXPECT_LE(std::fwide(stdout, 0), 0) << "stdout must not have become wide-oriented";
    EXPECT_GT(std::printf("%s", ""), -1);
}

}  // namespace
}  // namespace graspsim::system
