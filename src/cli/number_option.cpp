#include "number_option.h"

#include "graspsim/error.h"
#include "graspsim/io/number_text.h"

#include <cmath>


namespace graspsim::cli {

int parseCount(const std::string& text, const std::string& flag) {
    const double value = parseNumber(text, flag, "a whole number >= 1");
    if (!(value >= 1 && value <= 100000 && value == static_cast<int>(value))) {
        throw InputError(flag + ": value " + text + " is not accepted; give a whole number >= 1");
    }
    return static_cast<int>(value);
}

double parseAccuracy(const std::string& text) {
    if (text.empty()) return 0;
    const double value = parseNumber(text, "--accuracy", "a number in (0, 1)");
    if (!(value > 0 && value < 1)) throw InputError("--accuracy: value " + text + " is not accepted; use a number in (0, 1)");
    return value;
}

double parseStepSize(const std::string& text) { return parsePositiveNumber(text, "--step-size", "s").value_or(0); }

std::optional<double> parseReleaseGive(const std::string& text) { return parsePositiveNumber(text, "--release-give", "m"); }

}  // namespace graspsim::cli
