#include "graspsim/io/number_text.h"

#include "graspsim/error.h"

#include <cmath>
#include <cstdlib>

namespace graspsim::io {

double parseNumber(const std::string& text, const std::string& what, const std::string& accepted) {
    const char* begin = text.c_str();
    char* end = nullptr;
    const double value = std::strtod(begin, &end);
    if (text.empty() || end != begin + text.size()) {
        throw InputError(what + ": value '" + text + "' is not a number; " + accepted);
    }
    return value;
}

std::optional<double> parsePositiveNumber(const std::string& text, const std::string& what, const std::string& unit) {
    if (text.empty()) return std::nullopt;
    const std::string accepted = "a finite number > 0 (" + unit + ")";
    const double value = parseNumber(text, what, accepted);
    if (!(value > 0 && std::isfinite(value))) throw InputError(what + ": value " + text + " is not accepted; use " + accepted);
    return value;
}

double parseNonNegativeNumber(const std::string& text, const std::string& what, const std::string& unit) {
    if (text.empty()) return 0;
    const std::string accepted = "a finite number >= 0 (" + unit + ")";
    const double value = parseNumber(text, what, accepted);
    if (!(value >= 0 && std::isfinite(value))) throw InputError(what + ": value " + text + " is not accepted; use " + accepted);
    return value;
}

}  // namespace graspsim::io
