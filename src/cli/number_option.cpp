#include "number_option.h"

#include "graspsim/error.h"

#include <cmath>
#include <cstdlib>

namespace graspsim::cli {

double parseNumber(const std::string& text, const std::string& flag, const std::string& accepted) {
    const char* begin = text.c_str();
    char* end = nullptr;
    const double value = std::strtod(begin, &end);
    if (text.empty() || end != begin + text.size()) {
        throw InputError(flag + ": value '" + text + "' is not a number; " + accepted);
    }
    return value;
}

double parseAccuracy(const std::string& text) {
    if (text.empty()) return 0;
    const double value = parseNumber(text, "--accuracy", "a number in (0, 1)");
    if (!(value > 0 && value < 1)) throw InputError("--accuracy: value " + text + " is not accepted; use a number in (0, 1)");
    return value;
}

double parseStepSize(const std::string& text) {
    if (text.empty()) return 0;
    const double value = parseNumber(text, "--step-size", "a finite number > 0 (s)");
    if (!(value > 0 && std::isfinite(value))) {
        throw InputError("--step-size: value " + text + " is not accepted; use a finite number > 0 (s)");
    }
    return value;
}

std::optional<double> parseReleaseGive(const std::string& text) {
    if (text.empty()) return std::nullopt;
    const double value = parseNumber(text, "--release-give", "a finite number > 0 (m)");
    if (!(value > 0 && std::isfinite(value))) {
        throw InputError("--release-give: value " + text + " is not accepted; use a finite number > 0 (m)");
    }
    return value;
}

}  // namespace graspsim::cli
