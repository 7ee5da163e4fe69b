#pragma once
/// @file
/// Finger segment lengths as fractions of hand length (Buchholz et al. 1992).
///
/// Source: Buchholz B., Armstrong T.J., Goldstein S.A. (1992) "Anthropometric data for
/// describing the kinematics of the human hand", Ergonomics 35(3):261-273, embedded from
/// anthropometry/buchholz_1992_segment_lengths.csv. Hand length is measured from the distal
/// wrist crease to the tip of the middle finger (not de Leva's WJC-MET3 "hand" segment).

#include <string>

namespace graspsim::anthropometry {

/// The five digits, radial to ulnar.
enum class Digit { Thumb, Index, Middle, Ring, Little };

/// "thumb", "index", "middle", "ring" or "little", the spelling of the CSV file.
std::string toString(Digit digit);

/// Segment lengths of one digit, each a fraction of hand length (dimensionless).
struct DigitLengths {
    double metacarpal = 0.0;  ///< CMC to MCP joint centre
    double proximal = 0.0;    ///< MCP to PIP (thumb: MCP to IP) joint centre
    double middle = 0.0;      ///< PIP to DIP joint centre; 0 for the thumb, which has none
    double distal = 0.0;      ///< DIP (thumb: IP) joint centre to the digit tip
};

/// The Buchholz (1992) coefficients for all five digits.
class FingerTable {
public:
    /// The embedded Buchholz (1992) table.
    static FingerTable loadBuchholz();

    /// Parses a table in the format of anthropometry/buchholz_1992_segment_lengths.csv
    /// (columns digit, segment, length_per_hand_length). Every digit needs metacarpal,
    /// proximal and distal; the fingers also need middle and the thumb must not have one.
    static FingerTable parseCsv(const std::string& csvText, const std::string& source);

    const DigitLengths& getDigit(Digit digit) const;

private:
    FingerTable() = default;

    DigitLengths m_digits[5];
};

}  // namespace graspsim::anthropometry
