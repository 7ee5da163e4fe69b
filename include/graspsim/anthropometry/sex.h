#pragma once
/// @file
/// The sex column of the anthropometric tables (de Leva 1996 tabulates females and males).

#include <string>

namespace graspsim::anthropometry {

/// Which column of a sex-specific anthropometric table to use.
enum class Sex { Female, Male };

/// Parses "female" or "male" (exact, lower case). `source` names where the text came from
/// (a file and line, or a command-line flag) and starts the InputError message:
/// "<source>: sex 'x' is not accepted; use male or female".
Sex parseSex(const std::string& text, const std::string& source);

/// "female" or "male", the spelling parseSex() accepts.
std::string toString(Sex sex);

}  // namespace graspsim::anthropometry
