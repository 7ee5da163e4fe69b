#include "graspsim/contact/friction_settings.h"

#include <cmath>
#include <sstream>

#include "graspsim/error.h"

namespace graspsim::contact {

namespace {

void checkPositive(const std::string& source, const std::string& field, double value, const std::string& unit) {
    if (std::isfinite(value) && value > 0) return;
    std::ostringstream message;
    message << source << ": " << field << " (" << value << ") must be finite and > 0" << unit;
    throw InputError(message.str());
}

}  // namespace

std::string toString(FrictionModel model) {
    return model == FrictionModel::Anchor ? "anchor" : "regularized";
}

FrictionModel parseFrictionModel(const std::string& text, const std::string& source) {
    if (text == "regularized") return FrictionModel::Regularized;
    if (text == "anchor") return FrictionModel::Anchor;
    throw InputError(source + ": '" + text + "' is not accepted; use regularized or anchor");
}

void AnchorFrictionParameters::validate(const std::string& source) const {
    checkPositive(source, "anchor stiffness ratio", stiffnessRatio, " (k_t / k_n, dimensionless)");
    checkPositive(source, "anchor damping mass", dampingMass, " (kg)");
    checkPositive(source, "anchor relaxation time", relaxationTime, " (s)");
}

}  // namespace graspsim::contact
