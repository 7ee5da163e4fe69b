#include "urdf_text.h"

#include <cstdio>

namespace graspsim::model {

namespace {

// Length of the UTF-8 sequence starting with `lead`, 0 if it cannot start one (RFC 3629:
// no continuation bytes, no overlong two-byte leads 0xC0-0xC1, nothing above 0xF4).
int findSequenceLength(unsigned char lead) {
    if (lead < 0x80) return 1;
    if (lead >= 0xC2 && lead <= 0xDF) return 2;
    if (lead >= 0xE0 && lead <= 0xEF) return 3;
    if (lead >= 0xF0 && lead <= 0xF4) return 4;
    return 0;
}

// Whether the n-byte sequence at `s` is well formed: continuation bytes 10xxxxxx, and the second
// byte's range narrowed where RFC 3629 forbids overlong forms, surrogates and code points > U+10FFFF.
bool isWellFormed(const unsigned char* s, int n) {
    for (int k = 1; k < n; ++k) {
        if ((s[k] & 0xC0) != 0x80) return false;
    }
    if (n == 3 && s[0] == 0xE0 && s[1] < 0xA0) return false;
    if (n == 3 && s[0] == 0xED && s[1] > 0x9F) return false;
    if (n == 4 && s[0] == 0xF0 && s[1] < 0x90) return false;
    if (n == 4 && s[0] == 0xF4 && s[1] > 0x8F) return false;
    return true;
}

std::string describeByte(unsigned char byte) {
    char text[8];
    std::snprintf(text, sizeof text, "0x%02x", byte);
    return text;
}

}  // namespace

void checkUrdfText(const std::string& text, const UrdfSource& source) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(text.data());
    const std::size_t size = text.size();
    int line = 1;
    for (std::size_t i = 0; i < size;) {
        if (bytes[i] == 0) source.reject(line, "byte " + std::to_string(i), "0x00", "URDF is text; a NUL byte is not");
        const int n = findSequenceLength(bytes[i]);
        if (n == 0 || i + static_cast<std::size_t>(n) > size || !isWellFormed(bytes + i, n)) {
            source.reject(line, "byte " + std::to_string(i), describeByte(bytes[i]),
                          "URDF text must be UTF-8 (or ASCII); this byte does not start a complete UTF-8 sequence");
        }
        if (bytes[i] == '\n') ++line;
        i += static_cast<std::size_t>(n);
    }
}

}  // namespace graspsim::model
