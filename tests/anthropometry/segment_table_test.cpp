#include <graspsim/anthropometry/segment_table.h>

#include <graspsim/error.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

namespace graspsim::anthropometry {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::StrEq;
using ::testing::ThrowsMessage;

// Two-decimal percentages: eleven rounded entries can be off by 0.005 % each (< 0.0002).
constexpr double kRoundingTolerance = 0.0002;

const char* const kSegmentNames[] = {"head",      "trunk",   "upper_trunk", "middle_trunk",
                                     "lower_trunk", "upper_arm", "forearm", "hand",
                                     "thigh",     "shank",   "foot"};

const char* const kHeader =
    "sex,segment,proximal_landmark,distal_landmark,length_mm,mass_pct,com_pct,"
    "r_sagittal_pct,r_transverse_pct,r_longitudinal_pct\n";

class DeLevaTable : public ::testing::TestWithParam<Sex> {};

TEST_P(DeLevaTable, HasEverySegmentOfTheMainTable) {
    const SegmentTable table = SegmentTable::loadDeLeva(GetParam());
    EXPECT_EQ(table.getSex(), GetParam());
    EXPECT_EQ(table.getSegments().size(), std::size(kSegmentNames));
    for (const char* name : kSegmentNames) EXPECT_NO_THROW(table.getSegment(name)) << name;
}

TEST_P(DeLevaTable, WholeBodyMassFractionsSumToOne) {
    const SegmentTable table = SegmentTable::loadDeLeva(GetParam());
    EXPECT_NEAR(table.calcWholeBodyMassFractionSum(), 1.0, kRoundingTolerance);
}

TEST_P(DeLevaTable, TrunkPartsSumToTrunk) {
    const SegmentTable table = SegmentTable::loadDeLeva(GetParam());
    EXPECT_NEAR(table.calcTrunkPartsMassFractionSum(), table.getSegment("trunk").massFraction,
                kRoundingTolerance);
}

// The sub-trunks split SUPR-MIDH at XYPH and OMPH, so their lengths add up to the trunk's.
TEST_P(DeLevaTable, TrunkPartLengthsSumToTrunkLength) {
    const SegmentTable table = SegmentTable::loadDeLeva(GetParam());
    const double parts = table.getSegment("upper_trunk").length +
                         table.getSegment("middle_trunk").length +
                         table.getSegment("lower_trunk").length;
    EXPECT_NEAR(parts, table.getSegment("trunk").length, 0.0001);
    EXPECT_EQ(table.getSegment("trunk").proximalLandmark, "SUPR");
    EXPECT_EQ(table.getSegment("upper_trunk").proximalLandmark, "SUPR");
    EXPECT_EQ(table.getSegment("lower_trunk").distalLandmark, "MIDH");
}

TEST_P(DeLevaTable, EveryFractionIsInItsRange) {
    const SegmentTable table = SegmentTable::loadDeLeva(GetParam());  // not a temporary: the loop reads its rows
    for (const SegmentParameters& segment : table.getSegments()) {
        EXPECT_GT(segment.length, 0.05) << segment.name;  // metres, not millimetres
        EXPECT_LT(segment.length, 0.7) << segment.name;
        EXPECT_GT(segment.massFraction, 0.0) << segment.name;
        EXPECT_LT(segment.massFraction, 0.5) << segment.name;
        EXPECT_GT(segment.comFraction, 0.0) << segment.name;
        EXPECT_LT(segment.comFraction, 1.0) << segment.name;
        for (double r : {segment.gyrationSagittal, segment.gyrationTransverse,
                         segment.gyrationLongitudinal}) {
            EXPECT_GT(r, 0.0) << segment.name;
            EXPECT_LT(r, 1.0) << segment.name;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(BothSexes, DeLevaTable, ::testing::Values(Sex::Female, Sex::Male),
                         [](const auto& testInfo) { return toString(testInfo.param); });

TEST(SegmentTable, MaleHandRowIsConvertedToSiAndFractions) {
    const SegmentTable table = SegmentTable::loadDeLeva(Sex::Male);  // the row lives in the table
    const SegmentParameters& hand = table.getSegment("hand");
    EXPECT_EQ(hand.proximalLandmark, "WJC");
    EXPECT_EQ(hand.distalLandmark, "MET3");
    EXPECT_DOUBLE_EQ(hand.length, 0.0862);
    EXPECT_DOUBLE_EQ(hand.massFraction, 0.0061);
    EXPECT_DOUBLE_EQ(hand.comFraction, 0.79);
    EXPECT_DOUBLE_EQ(hand.gyrationSagittal, 0.628);
    EXPECT_DOUBLE_EQ(hand.gyrationTransverse, 0.513);
    EXPECT_DOUBLE_EQ(hand.gyrationLongitudinal, 0.401);
}

TEST(SegmentTable, FemaleRowsAreKeptApartFromMaleRows) {
    const SegmentTable table = SegmentTable::loadDeLeva(Sex::Female);
    const SegmentParameters& head = table.getSegment("head");
    EXPECT_DOUBLE_EQ(head.length, 0.2002);
    EXPECT_DOUBLE_EQ(head.massFraction, 0.0668);
}

TEST(SegmentTable, UnknownSegmentListsKnownNames) {
    const SegmentTable table = SegmentTable::loadDeLeva(Sex::Male);
    EXPECT_THAT([&] { table.getSegment("pelvis"); },
                ThrowsMessage<InputError>(AllOf(
                    HasSubstr("anthropometry/de_leva_1996_table4.csv: segment 'pelvis'"),
                    HasSubstr("known segments: head, trunk, upper_trunk, middle_trunk, "
                              "lower_trunk, upper_arm, forearm, hand, thigh, shank, foot"))));
}

TEST(SegmentTable, ParseCsvRejectsNonNumericFieldNamingFileLineAndField) {
    const std::string text = std::string("# comment\n") + kHeader +
                             "male,head,VERT,MIDG,203.3,abc,59.76,36.2,37.6,31.2\n";
    EXPECT_THAT([&] { SegmentTable::parseCsv(text, Sex::Male, "bad.csv"); },
                ThrowsMessage<InputError>(
                    StrEq("bad.csv:3: field 'mass_pct' value 'abc' is not a number")));
}

TEST(SegmentTable, ParseCsvRejectsOutOfRangePercentages) {
    const std::string text =
        std::string(kHeader) + "male,head,VERT,MIDG,203.3,6.94,120,36.2,37.6,31.2\n";
    EXPECT_THAT([&] { SegmentTable::parseCsv(text, Sex::Male, "bad.csv"); },
                ThrowsMessage<InputError>(StrEq(
                    "bad.csv:2: field 'com_pct' value '120' is not accepted; use a number in "
                    "[0, 100]")));
}

TEST(SegmentTable, ParseCsvRejectsUnknownSexDuplicatesAndMissingSex) {
    const std::string row = "male,head,VERT,MIDG,203.3,6.94,59.76,36.2,37.6,31.2\n";
    EXPECT_THAT([&] { SegmentTable::parseCsv(std::string(kHeader) + "m" + row.substr(4),
                                             Sex::Male, "bad.csv"); },
                ThrowsMessage<InputError>(HasSubstr("bad.csv:2: sex 'm' is not accepted")));
    EXPECT_THAT([&] { SegmentTable::parseCsv(kHeader + row + row, Sex::Male, "bad.csv"); },
                ThrowsMessage<InputError>(HasSubstr("bad.csv:3: segment 'head' appears twice")));
    EXPECT_THAT([&] { SegmentTable::parseCsv(kHeader + row, Sex::Female, "bad.csv"); },
                ThrowsMessage<InputError>(StrEq("bad.csv: no rows for sex 'female'")));
}

}  // namespace
}  // namespace graspsim::anthropometry
