#include "number_option.h"

#include "graspsim/error.h"

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

}  // namespace graspsim::cli
