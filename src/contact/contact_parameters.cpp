#include "graspsim/contact/contact_parameters.h"

#include <cmath>
#include <sstream>

#include "graspsim/error.h"

namespace graspsim::contact {

namespace {

[[noreturn]] void throwBadField(const std::string& source, const std::string& field, double value,
                                const std::string& accepted) {
    std::ostringstream message;
    message << source << ": " << field << " (" << value << ") must be " << accepted;
    throw InputError(message.str());
}

void checkNonNegative(const std::string& source, const std::string& field, double value,
                      const std::string& unit) {
    if (!(std::isfinite(value) && value >= 0)) {
        throwBadField(source, field, value, "finite and >= 0" + unit);
    }
}

void checkPositive(const std::string& source, const std::string& field, double value,
                   const std::string& unit) {
    if (!(std::isfinite(value) && value > 0)) {
        throwBadField(source, field, value, "finite and > 0" + unit);
    }
}

}  // namespace

std::string toString(CapsuleContact rule) {
    return rule == CapsuleContact::Ends ? "ends" : "deepest";
}

CapsuleContact parseCapsuleContact(const std::string& text, const std::string& source) {
    if (text == "deepest") return CapsuleContact::Deepest;
    if (text == "ends") return CapsuleContact::Ends;
    throw InputError(source + ": '" + text + "' is not accepted; use deepest or ends");
}

void ContactParameters::validate(const std::string& source) const {
    checkPositive(source, "effectiveStiffness", effectiveStiffness, " (Pa)");
    checkNonNegative(source, "dissipation", dissipation, " (s/m)");
    checkNonNegative(source, "staticFriction", staticFriction, "");
    checkNonNegative(source, "dynamicFriction", dynamicFriction, "");
    checkNonNegative(source, "viscousFriction", viscousFriction, " (s/m)");
    checkPositive(source, "transitionVelocity", transitionVelocity, " (m/s)");
    if (dynamicFriction > staticFriction) {
        std::ostringstream message;
        message << source << ": dynamicFriction (" << dynamicFriction
                << ") is greater than staticFriction (" << staticFriction
                << "); it must be <= staticFriction";
        throw InputError(message.str());
    }
}

}  // namespace graspsim::contact
