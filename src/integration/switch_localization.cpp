#include "switch_localization.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace graspsim::integration {

double SwitchLocalization::findWindow(const SimTK::System& system, double accuracy) {
    return accuracy * system.getDefaultTimeScale() * SimTK::EventTriggerInfo().getRequiredLocalizationTimeWindow();
}

std::vector<std::int64_t> SwitchLocalization::findLostTerms(std::vector<std::int64_t> start, std::vector<std::int64_t> end) {
    std::sort(start.begin(), start.end());
    std::sort(end.begin(), end.end());
    std::vector<std::int64_t> lost;
    std::set_difference(start.begin(), start.end(), end.begin(), end.end(), std::back_inserter(lost));
    return lost;
}

// A step that does not reach the switch is kept (progress), one that does shortens the bracket,
// so the steps toward it are never wasted twice. Bisection halves the bracket per attempt (about
// eight attempts from a millisecond to the 10 us window); an estimate from the margins, where they
// are near linear over the bracket, gets there in two: one step to just short of the switch, one
// window across it.
double SwitchLocalization::limitStep(double t, double h) const {
    if (!(t < end_)) return h;
    const double rest = end_ - t;
    if (rest <= window_) return std::min(h, rest);
    if (!std::isnan(estimate_)) {
        const double ahead = estimate_ - t;
        if (ahead > 0) return std::min(h, ahead > window_ ? ahead - 0.5 * window_ : window_);
        // Past the estimate without losing the term: the rest in one step, which crosses (a new
        // bracket and estimate) or shows the long step's loss was its own error.
        return std::min(h, rest);
    }
    return std::min(h, rest / 2);
}

bool SwitchLocalization::crossed(double t, double h) {
    if (h <= window_) return false;
    if (!(t < end_)) estimates_ = 0;  // a switch not bracketed before
    end_ = t + h;
    estimate_ = SimTK::NaN;
    return true;
}

void SwitchLocalization::setEstimate(double time) {
    if (std::isnan(time) || !(time < end_) || ++estimates_ > kMaxEstimates) return;
    estimate_ = time;
}

}  // namespace graspsim::integration
