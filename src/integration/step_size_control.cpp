#include "step_size_control.h"

#include <algorithm>
#include <cmath>

namespace graspsim::integration {

double StepSizeControl::getProposal() const { return std::min(next_, longest_); }

// A stop closer than 1.5 p is reached in one or two equal steps, so no sliver step is left. When
// p is within kStepStretch of the cap h, a stop up to kMaxEqualSteps h away is reached in the
// fewest equal steps no longer than h: engaged, with the IK's events every 10 ms and h 5 ms, the
// error's proposals of 4.5 ms took three steps per interval (4.5 ms and two of 2.75 ms) where two
// of 5 ms pass the error test (error about 0.6 of the accuracy). That is the growth rule's safety
// factor 0.9 moved toward 1 for steps at the cap only (stretching shorter steps too moved the
// phone's orientation error from 0.44 to 0.53 degrees), and not right after a rejection (the step
// taken again must be shorter than the one rejected).
double StepSizeControl::findStepToStop(double remaining) const {
    const double h = longest_, proposal = getProposal();
    if (!justRejected_ && kStepStretch * proposal >= h && remaining <= kMaxEqualSteps * h) {
        return remaining / std::ceil(remaining / h * (1 - 1e-12));
    }
    if (remaining < 1.5 * proposal) return remaining <= proposal ? remaining : remaining / 2;
    return proposal;
}

// The usual second-order rule, 0.9 error^(-1/2), between 0.2x and 5x; no growth right after a
// rejection (Hairer and Wanner's rule): the step that just passed is near the limit, and growing
// it again mostly buys another rejection.
bool StepSizeControl::acceptStep(double h, double error) {
    const double factor = std::clamp(0.9 / std::sqrt(std::max(error, 1e-10)), 0.2, 5.0);
    if (error <= 1 || h <= kMinStepSize) {
        next_ = h * (justRejected_ ? std::min(factor, 1.0) : factor);
        justRejected_ = false;
        return true;
    }
    next_ = h * factor;
    justRejected_ = true;
    return false;
}

void StepSizeControl::restart(double h) {
    next_ = h;
    justRejected_ = false;
}

}  // namespace graspsim::integration
