#pragma once
// Where URDF text came from, so that every import error names the file and, when known, the line.

#include <string>

namespace graspsim::model {

/// The origin of URDF text being read (a file name, or a description such as "<string>").
struct UrdfSource {
    std::string name;

    /// Throws graspsim::InputError "<name>:<line>: <field> = <value> is not accepted; <accepted>"
    /// (the ":<line>" part only when line > 0), the format ModelDescription::validate uses.
    [[noreturn]] void reject(int line, const std::string& field, const std::string& value,
                             const std::string& accepted) const;

    /// Throws graspsim::InputError "<name>:<line>: <message>" for errors that are not one field.
    [[noreturn]] void fail(int line, const std::string& message) const;
};

/// `text` in single quotes, as names and enumerated values appear in messages.
std::string quoted(const std::string& text);

}  // namespace graspsim::model
