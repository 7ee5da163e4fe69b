#include <graspsim/anthropometry/finger_table.h>

#include <graspsim/error.h>

#include "csv_table.h"
#include "embedded_tables.h"

#include <utility>

namespace graspsim::anthropometry {

namespace {

const char* const kBuchholzFile = "buchholz_1992_segment_lengths.csv";
constexpr Digit kDigits[] = {Digit::Thumb, Digit::Index, Digit::Middle, Digit::Ring,
                             Digit::Little};
constexpr double kUnset = -1.0;  // marks a segment no row has given yet

Digit parseDigit(const std::string& text, const std::string& where) {
    for (Digit digit : kDigits) {
        if (toString(digit) == text) return digit;
    }
    throw InputError(where + ": digit '" + text +
                     "' is not accepted; use thumb, index, middle, ring or little");
}

double* findSegment(DigitLengths& lengths, const std::string& segment, const std::string& where) {
    if (segment == "metacarpal") return &lengths.metacarpal;
    if (segment == "proximal") return &lengths.proximal;
    if (segment == "middle") return &lengths.middle;
    if (segment == "distal") return &lengths.distal;
    throw InputError(where + ": segment '" + segment +
                     "' is not accepted; use metacarpal, proximal, middle or distal");
}

// Every digit must be complete; the thumb has no middle phalanx, so its middle stays 0.
void checkComplete(DigitLengths& lengths, Digit digit, const std::string& source) {
    const std::string name = toString(digit);
    if (digit == Digit::Thumb) {
        if (lengths.middle != kUnset) {
            throw InputError(source + ": the thumb has no middle phalanx; remove thumb,middle");
        }
        lengths.middle = 0.0;
    }
    const std::pair<double, const char*> segments[] = {{lengths.metacarpal, "metacarpal"},
                                                       {lengths.proximal, "proximal"},
                                                       {lengths.middle, "middle"},
                                                       {lengths.distal, "distal"}};
    for (const auto& [value, segment] : segments) {
        if (value == kUnset) {
            throw InputError(source + ": no row for digit '" + name + "' segment '" +
                             segment + "'");
        }
    }
}

}  // namespace

std::string toString(Digit digit) {
    switch (digit) {
        case Digit::Thumb: return "thumb";
        case Digit::Index: return "index";
        case Digit::Middle: return "middle";
        case Digit::Ring: return "ring";
        case Digit::Little: return "little";
    }
    return "unknown";
}

FingerTable FingerTable::loadBuchholz() {
    return parseCsv(std::string(findEmbeddedTable(kBuchholzFile)),
                    findEmbeddedTableSource(kBuchholzFile));
}

FingerTable FingerTable::parseCsv(const std::string& csvText, const std::string& source) {
    const CsvTable table = CsvTable::parse(csvText, source);
    table.requireColumns({"digit", "segment", "length_per_hand_length"});
    FingerTable fingers;
    for (DigitLengths& lengths : fingers.m_digits) lengths = {kUnset, kUnset, kUnset, kUnset};
    for (std::size_t row = 0; row < table.getRowCount(); ++row) {
        const std::string where = table.findLocation(row);
        const Digit digit = parseDigit(table.getText(row, "digit"), where);
        const std::string& segment = table.getText(row, "segment");
        double* length = findSegment(fingers.m_digits[static_cast<int>(digit)], segment, where);
        if (*length != kUnset) {
            throw InputError(where + ": digit '" + toString(digit) + "' segment '" + segment +
                             "' appears twice");
        }
        *length = table.getNumber(row, "length_per_hand_length");
        if (*length <= 0.0 || *length >= 1.0) {
            throw InputError(where + ": field 'length_per_hand_length' value '" +
                             table.getText(row, "length_per_hand_length") +
                             "' is not accepted; use a fraction of hand length in (0, 1)");
        }
    }
    for (Digit digit : kDigits) {
        checkComplete(fingers.m_digits[static_cast<int>(digit)], digit, source);
    }
    return fingers;
}

const DigitLengths& FingerTable::getDigit(Digit digit) const {
    return m_digits[static_cast<int>(digit)];
}

}  // namespace graspsim::anthropometry
