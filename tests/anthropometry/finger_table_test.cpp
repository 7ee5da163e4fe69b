#include <graspsim/anthropometry/finger_table.h>

#include <graspsim/error.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

namespace graspsim::anthropometry {
namespace {

using ::testing::HasSubstr;
using ::testing::StrEq;
using ::testing::ThrowsMessage;

const Digit kFingers[] = {Digit::Index, Digit::Middle, Digit::Ring, Digit::Little};

TEST(FingerTable, MiddleDigitPhalangesAreShorterThanTheHand) {
    const FingerTable table = FingerTable::loadBuchholz();
    const DigitLengths& middle = table.getDigit(Digit::Middle);
    const double phalanges = middle.proximal + middle.middle + middle.distal;
    EXPECT_LT(phalanges, 1.0);
    // Hand length also spans the metacarpal and the carpus, so even with it the sum is < 1.
    EXPECT_LT(middle.metacarpal + phalanges, 1.0);
}

TEST(FingerTable, ThumbHasNoMiddlePhalanx) {
    const FingerTable table = FingerTable::loadBuchholz();
    const DigitLengths& thumb = table.getDigit(Digit::Thumb);
    EXPECT_DOUBLE_EQ(thumb.middle, 0.0);
    EXPECT_DOUBLE_EQ(thumb.metacarpal, 0.251);
    EXPECT_DOUBLE_EQ(thumb.proximal, 0.196);
    EXPECT_DOUBLE_EQ(thumb.distal, 0.158);
}

TEST(FingerTable, FingersHaveFourPositiveSegmentsShrinkingDistally) {
    const FingerTable table = FingerTable::loadBuchholz();
    for (Digit digit : kFingers) {
        const DigitLengths& lengths = table.getDigit(digit);
        EXPECT_GT(lengths.metacarpal, lengths.proximal) << toString(digit);
        EXPECT_GT(lengths.proximal, lengths.middle) << toString(digit);
        EXPECT_GT(lengths.middle, lengths.distal) << toString(digit);
        EXPECT_GT(lengths.distal, 0.0) << toString(digit);
    }
    EXPECT_DOUBLE_EQ(table.getDigit(Digit::Index).metacarpal, 0.374);
    EXPECT_DOUBLE_EQ(table.getDigit(Digit::Little).distal, 0.093);
}

TEST(FingerTable, DigitNamesMatchTheCsvSpelling) {
    EXPECT_EQ(toString(Digit::Thumb), "thumb");
    EXPECT_EQ(toString(Digit::Little), "little");
}

TEST(FingerTable, ParseCsvRejectsIncompleteOrWrongTables) {
    const std::string header = "digit,segment,length_per_hand_length\n";
    EXPECT_THAT([&] { FingerTable::parseCsv(header + "pinky,distal,0.09\n", "f.csv"); },
                ThrowsMessage<InputError>(HasSubstr("f.csv:2: digit 'pinky' is not accepted")));
    EXPECT_THAT([&] { FingerTable::parseCsv(header + "thumb,distal,1.5\n", "f.csv"); },
                ThrowsMessage<InputError>(HasSubstr(
                    "f.csv:2: field 'length_per_hand_length' value '1.5' is not accepted")));
    EXPECT_THAT([&] { FingerTable::parseCsv(header + "thumb,distal,0.158\n", "f.csv"); },
                ThrowsMessage<InputError>(
                    StrEq("f.csv: no row for digit 'thumb' segment 'metacarpal'")));
}

}  // namespace
}  // namespace graspsim::anthropometry
