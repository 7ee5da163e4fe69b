#pragma once
/// @file
/// Numbers typed by a user (a command-line flag's value, a study's run option), parsed whole, so
/// that a bad value gets one line naming where it came from, the value and what is accepted.

#include <optional>
#include <string>

namespace graspsim::io {

/// Parses the whole of `text` as a double; NaN and infinities parse (the caller's range check
/// refuses them, naming the range).
/// @param what where the value came from, as the message names it ("--rate", "run option 'rate'")
/// @throws graspsim::InputError "<what>: value '<text>' is not a number; <accepted>"
double parseNumber(const std::string& text, const std::string& what, const std::string& accepted);

/// A finite number > 0 in `unit` (named in the message); empty text gives none.
/// @throws graspsim::InputError "<what>: value <text> is not accepted; use a finite number > 0 (<unit>)"
std::optional<double> parsePositiveNumber(const std::string& text, const std::string& what, const std::string& unit);

/// A finite number >= 0 in `unit`; empty text gives 0.
/// @throws graspsim::InputError "<what>: value <text> is not accepted; use a finite number >= 0 (<unit>)"
double parseNonNegativeNumber(const std::string& text, const std::string& what, const std::string& unit);

}  // namespace graspsim::io
