#include "urdf_number.h"

#include <charconv>
#include <system_error>

namespace graspsim::model {

namespace {

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

std::string_view trim(std::string_view text) {
    while (!text.empty() && isSpace(text.front())) text.remove_prefix(1);
    while (!text.empty() && isSpace(text.back())) text.remove_suffix(1);
    return text;
}

}  // namespace

std::string formatUrdfNumber(double value) {
    // std::to_chars without a precision gives the shortest text that round-trips exactly,
    // which is both lossless and as readable as the value allows.
    // -0 reads as a surprise and compares equal to 0, so it is written as 0.
    if (value == 0) value = 0;
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
    return std::string(buffer, result.ptr);
}

std::string formatUrdfTriple(const Vec3& v) {
    return formatUrdfNumber(v[0]) + " " + formatUrdfNumber(v[1]) + " " + formatUrdfNumber(v[2]);
}

std::optional<double> parseUrdfNumber(std::string_view text) {
    text = trim(text);
    // from_chars rejects a leading '+', which people do write by hand.
    if (text.size() > 1 && text.front() == '+' && text[1] != '-') text.remove_prefix(1);
    if (text.empty()) return std::nullopt;
    double value = 0;
    const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
    if (result.ec != std::errc() || result.ptr != text.data() + text.size()) return std::nullopt;
    return value;
}

std::optional<Vec3> parseUrdfTriple(std::string_view text) {
    Vec3 v{0, 0, 0};
    std::size_t count = 0;
    text = trim(text);
    while (!text.empty()) {
        std::size_t end = 0;
        while (end < text.size() && !isSpace(text[end])) ++end;
        const std::optional<double> value = parseUrdfNumber(text.substr(0, end));
        if (!value || count == 3) return std::nullopt;
        v[count++] = *value;
        text = trim(text.substr(end));
    }
    if (count != 3) return std::nullopt;
    return v;
}

}  // namespace graspsim::model
