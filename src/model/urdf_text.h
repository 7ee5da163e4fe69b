#pragma once
// The bytes of URDF text, checked before any XML parser sees them. Debian's TinyXML 2.6.2 trusts
// UTF-8 lead bytes: a truncated multi-byte sequence makes it step over the string's terminator
// and read past the end of the buffer (found by the URDF fuzzer under AddressSanitizer).

#include "urdf_source.h"

#include <string>

namespace graspsim::model {

/// Accepts `text` if it is well-formed UTF-8 (ASCII included) without NUL bytes.
/// @throws graspsim::InputError naming the source, the line and the first bad byte, otherwise.
void checkUrdfText(const std::string& text, const UrdfSource& source);

}  // namespace graspsim::model
