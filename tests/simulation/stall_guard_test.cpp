// The stall guard's rule: a mean step below 1 us over an advance of at least 1 ms.
#include "graspsim/simulation/stall_guard.h"

#include "graspsim/error.h"

#include <gtest/gtest.h>

#include <string>

namespace graspsim::simulation {
namespace {

TEST(StallGuard, AMeanStepBelowTheBoundOverTheWindowIsAStallNamedWithItsFigures) {
    // 2 ms in 4000 steps: 0.5 us.
    try {
        checkNotStalled("simulation", 3.0, 3.002, 4000);
        ADD_FAILURE() << "no stall reported";
    } catch (const NumericalError& e) {
        const std::string text = e.what();
        EXPECT_EQ(text.rfind("simulation: the integrator stalled between t = 3 and 3.002 s: 4000 steps, a mean step of 5e-07 s", 0), 0u)
            << text;
    }
    EXPECT_NO_THROW(checkNotStalled("simulation", 3.0, 3.002, 1999));      // 1.0005 us
    EXPECT_NO_THROW(checkNotStalled("simulation", 3.0, 3.0009, 100000));   // under the 1 ms window
    EXPECT_NO_THROW(checkNotStalled("simulation", 3.0, 3.002, 0));         // a restart reset the count
    EXPECT_NO_THROW(checkNotStalled("simulation", 3.0, 3.002, -5));
}

}  // namespace
}  // namespace graspsim::simulation
