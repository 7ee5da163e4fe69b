#pragma once
// Numbers as URDF text: written so they read back bit for bit, read strictly in the "C" locale.

#include "graspsim/model/model_description.h"

#include <optional>
#include <string>
#include <string_view>

namespace graspsim::model {

/// Shortest decimal text that reads back as exactly `value` ("0.1", "1.5707963267948966",
/// "1e-05"); never depends on the global locale.
std::string formatUrdfNumber(double value);

/// Three numbers separated by single spaces: URDF's xyz, rpy and size attribute form.
std::string formatUrdfTriple(const Vec3& v);

/// One decimal number (an optional leading '+' or '-', then digits, '.', exponent), or nullopt
/// when `text` is anything else. Surrounding white space is ignored. "nan" and "inf" are read
/// as such so callers can name them in their message.
std::optional<double> parseUrdfNumber(std::string_view text);

/// Exactly three numbers separated by white space, or nullopt.
std::optional<Vec3> parseUrdfTriple(std::string_view text);

}  // namespace graspsim::model
