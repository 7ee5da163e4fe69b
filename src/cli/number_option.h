#pragma once
// Parsing numeric command-line values ourselves, so a bad value gets graspsim's one-line message
// naming the flag, the value and what is accepted, rather than CLI11's generic text.

#include "graspsim/io/number_text.h"

#include <optional>
#include <string>

namespace graspsim::cli {

// A flag's number (io/number_text.h): "<flag>: value ... is not accepted; ...".
using io::parseNumber;
using io::parseNonNegativeNumber;
using io::parsePositiveNumber;

// A whole number >= 1 (a count: --jobs, --array-size). Throws InputError naming the flag.
int parseCount(const std::string& text, const std::string& flag);

// --accuracy: an integrator relative accuracy in (0, 1); empty keeps the scenario's (returns 0).
double parseAccuracy(const std::string& text);

// --step-size: the fixed step (s), finite and > 0; empty keeps the scenario's (returns 0).
double parseStepSize(const std::string& text);
// --release-give: metres, finite and > 0; empty leaves it unset (the default give).
std::optional<double> parseReleaseGive(const std::string& text);

}  // namespace graspsim::cli
