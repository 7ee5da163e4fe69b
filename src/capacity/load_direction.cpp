#include "graspsim/capacity/load_direction.h"

#include "graspsim/error.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace graspsim::capacity {

namespace {

const char* const kAccepted = "use x, y, z, -x, -y, -z or three numbers such as 0,-1,0 (not all zero)";

bool parseVector(std::string text, SimTK::Vec3& v) {
    for (char& c : text) if (c == ',') c = ' ';
    std::istringstream in(text);
    in.imbue(std::locale::classic());
    for (int k = 0; k < 3; ++k) if (!(in >> v[k])) return false;
    std::string rest;
    return !(in >> rest);
}

}  // namespace

std::vector<LoadDirection> findAxisDirections() {
    std::vector<LoadDirection> axes;
    const char* const names[] = {"x", "y", "z"};
    for (int k = 0; k < 3; ++k) {
        SimTK::Vec3 v(0);
        v[k] = 1;
        axes.push_back({names[k], SimTK::UnitVec3(v)});
        axes.push_back({std::string("-") + names[k], SimTK::UnitVec3(-v)});
    }
    return axes;
}

LoadDirection parseLoadDirection(const std::string& text, const std::string& source) {
    for (const LoadDirection& axis : findAxisDirections()) if (axis.name == text) return axis;
    SimTK::Vec3 v;
    if (!parseVector(text, v)) throw InputError(source + ": value '" + text + "' is not a direction; " + kAccepted);
    double largest = 0;
    for (int k = 0; k < 3; ++k) largest = std::max(largest, std::abs(v[k]));
    if (!std::isfinite(largest) || !(largest > 0)) {
        throw InputError(source + ": value '" + text + "' is not accepted (zero or non-finite); " + kAccepted);
    }
    // Only the direction matters: a vector whose norm overflows or underflows (1e200,1e200,0) is
    // scaled by its largest part first.
    const double norm = v.norm();
    if (std::isfinite(norm) && norm > 1e-150) return {text, SimTK::UnitVec3(v / norm, true)};
    const SimTK::Vec3 scaled = v / largest;
    return {text, SimTK::UnitVec3(scaled / scaled.norm(), true)};
}

}  // namespace graspsim::capacity
