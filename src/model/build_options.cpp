#include "graspsim/model/build_options.h"

#include "graspsim/error.h"

#include <cmath>
#include <sstream>

namespace graspsim::model {

BodyKind parseBodyKind(const std::string& text, const std::string& source) {
    if (text == "arm") return BodyKind::Arm;
    if (text == "humanoid") return BodyKind::Humanoid;
    throw InputError(source + ": body '" + text + "' is not accepted; use arm or humanoid");
}

Preset parsePreset(const std::string& text, const std::string& source) {
    if (text == "none") return Preset::None;
    if (text == "thesis") return Preset::Thesis;
    throw InputError(source + ": preset '" + text + "' is not accepted; use thesis (or none)");
}

std::string toString(BodyKind kind) { return kind == BodyKind::Arm ? "arm" : "humanoid"; }
std::string toString(Preset preset) { return preset == Preset::Thesis ? "thesis" : "none"; }

namespace {

void requireNonNegative(double value, const std::string& field, const std::string& unit) {
    if (std::isfinite(value) && value >= 0) return;
    std::ostringstream msg;
    msg << field << ": value " << value << " is not accepted; it must be a finite number >= 0 " << unit;
    throw InputError(msg.str());
}

}  // namespace

void validateBuildOptions(const BuildOptions& options) {
    anthropometry::validateSubject(options.subject, "subject");
    requireNonNegative(options.fingerStiffness, "finger stiffness", "N m/rad");
    requireNonNegative(options.fingerDamping, "finger damping", "N m s/rad");
    requireNonNegative(options.armStiffness, "arm stiffness", "N m/rad");
    requireNonNegative(options.armDamping, "arm damping", "N m s/rad");
    requireNonNegative(options.trunkDamping, "trunk damping", "N m s/rad");
}

}  // namespace graspsim::model
