#include "switch_localization.h"

#include <algorithm>

namespace graspsim::integration {

double SwitchLocalization::findWindow(const SimTK::System& system, double accuracy) {
    return accuracy * system.getDefaultTimeScale() * SimTK::EventTriggerInfo().getRequiredLocalizationTimeWindow();
}

bool SwitchLocalization::losesTerm(const std::vector<std::int64_t>& start, const std::vector<std::int64_t>& end) {
    std::vector<std::int64_t> a(start), b(end);
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    return !std::includes(b.begin(), b.end(), a.begin(), a.end());
}

// Bisection: a step that does not reach the switch is kept (progress), one that does shortens the
// bracket, so the bracket halves per attempt and the steps toward it are never wasted twice.
double SwitchLocalization::limitStep(double t, double h) const {
    if (!(t < end_)) return h;
    const double rest = end_ - t;
    return std::min(h, rest > window_ ? rest / 2 : rest);
}

bool SwitchLocalization::crossed(double t, double h) {
    if (h <= window_) return false;
    end_ = t + h;
    return true;
}

}  // namespace graspsim::integration
