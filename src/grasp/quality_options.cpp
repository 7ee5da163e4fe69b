#include "graspsim/grasp/quality_options.h"

#include "graspsim/error.h"

#include <cmath>
#include <sstream>

namespace graspsim::grasp {

void validate(const QualityOptions& options) {
    validateFrictionCone(options.mu, options.cone, options.edges);
    if (!std::isfinite(options.torqueScale) || options.torqueScale <= 0) {
        std::ostringstream msg;
        msg << "grasp quality: torqueScale (" << options.torqueScale
            << ") must be finite and > 0 (m)";
        throw InputError(msg.str());
    }
}

std::string toString(QualityMetric metric) {
    return metric == QualityMetric::MinSingularValue ? "min-singular-value" : "ferrari-canny";
}

QualityMetric parseQualityMetric(const std::string& text, const std::string& source) {
    if (text == "min-singular-value") return QualityMetric::MinSingularValue;
    if (text == "ferrari-canny") return QualityMetric::FerrariCanny;
    throw InputError(source + ": unknown grasp quality metric '" + text +
                     "' (accepted: min-singular-value, ferrari-canny)");
}

}  // namespace graspsim::grasp
