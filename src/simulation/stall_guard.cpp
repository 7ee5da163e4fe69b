#include "graspsim/simulation/stall_guard.h"

#include "graspsim/error.h"

#include <cstdio>

namespace graspsim::simulation {

void checkNotStalled(const std::string& who, double from, double to, long steps) {
    const double advance = to - from;
    if (advance < kStallWindow || steps <= 0 || advance / static_cast<double>(steps) >= kStalledMeanStep) return;
    char text[256];
    std::snprintf(text, sizeof text, "%s: the integrator stalled between t = %.6g and %.6g s: %ld steps, a mean step of %.3g s "
                  "(below %g s; contacts chattering)", who.c_str(), from, to, steps, advance / static_cast<double>(steps), kStalledMeanStep);
    throw NumericalError(text);
}

}  // namespace graspsim::simulation
