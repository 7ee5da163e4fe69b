#include <graspsim/anthropometry/sex.h>

#include <graspsim/error.h>

namespace graspsim::anthropometry {

Sex parseSex(const std::string& text, const std::string& source) {
    if (text == "female") return Sex::Female;
    if (text == "male") return Sex::Male;
    throw InputError(source + ": sex '" + text + "' is not accepted; use male or female");
}

std::string toString(Sex sex) {
    return sex == Sex::Female ? "female" : "male";
}

}  // namespace graspsim::anthropometry
