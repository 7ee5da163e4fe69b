#include "number_text.h"

#include <cstdio>

namespace graspsim::validation {

std::string formatExactNumber(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17g", value);
    return buffer;
}

std::string formatBriefNumber(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.3g", value);
    return buffer;
}

}  // namespace graspsim::validation
