#include "graspsim/contact/contact_material.h"

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

void ContactMaterial::validate(const std::string& source) const {
    checkPositive(source, "stiffness", stiffness, " (Pa)");
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

ContactMaterial ContactMaterial::fingerPad() {
    ContactMaterial skin;
    skin.stiffness = 0.5e6 / (1 - 0.5 * 0.5);
    skin.dissipation = 1.0;
    skin.staticFriction = 0.8;
    skin.dynamicFriction = 0.6;
    skin.viscousFriction = 0;
    skin.transitionVelocity = 1e-3;
    return skin;
}

ContactMaterial ContactMaterial::rigidPlastic() {
    ContactMaterial plastic;
    plastic.stiffness = 2.3e9 / (1 - 0.35 * 0.35);
    plastic.dissipation = 0.5;
    plastic.staticFriction = 0.8;
    plastic.dynamicFriction = 0.6;
    plastic.viscousFriction = 0;
    plastic.transitionVelocity = 1e-3;
    return plastic;
}

}  // namespace graspsim::contact
