#pragma once
/// @file
/// The exceptions graspsim throws. Library code throws; only `main` and tests catch.

#include <stdexcept>
#include <string>

namespace graspsim {

/// Base of every graspsim exception. The message is one line meant for a person.
class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message) : std::runtime_error(message) {}
};

/// Bad input from a user: a file, a field, a flag or a value outside what is accepted.
/// The message names the source (file or flag), the field, the value and what is accepted.
/// The CLI maps it to exit code 2.
class InputError : public Error {
public:
    explicit InputError(const std::string& message) : Error(message) {}
};

/// A numerical failure during a computation (NaN/Inf in the state, step-size collapse).
/// The CLI maps it to exit code 3.
class NumericalError : public Error {
public:
    explicit NumericalError(const std::string& message) : Error(message) {}
};

/// `text` with every run of line breaks, tabs and spaces folded into one space and the ends
/// trimmed: messages from other libraries (Simbody's span lines) made fit for one line.
inline std::string foldToOneLine(const std::string& text) {
    std::string line;
    bool gap = false;
    for (char c : text) {
        if (c == '\n' || c == '\r' || c == '\t' || c == ' ') {
            gap = !line.empty();
            continue;
        }
        if (gap) line += ' ';
        gap = false;
        line += c;
    }
    return line;
}

}  // namespace graspsim
