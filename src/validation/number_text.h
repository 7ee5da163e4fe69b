#pragma once
// How the validation layer writes numbers: exactly in its CSV files, briefly in report.md.
// Private to the layer.

#include <string>

namespace graspsim::validation {

// Round-trip text of a number (%.17g), as in the run files.
std::string formatExactNumber(double value);

// A number for people: 3 significant digits (%.3g).
std::string formatBriefNumber(double value);

}  // namespace graspsim::validation
