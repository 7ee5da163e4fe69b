#include <graspsim/anthropometry/proportion_table.h>

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

// The names the hand model reads; renaming one in the CSV must fail here, not in the model.
const char* const kRequiredNames[] = {
    "hand_length_per_stature",
    "hand_breadth_per_hand_length",
    "palm_thickness_per_hand_length",
    "finger_proximal_radius_per_hand_length",
    "finger_middle_radius_per_hand_length",
    "finger_distal_radius_per_hand_length",
    "thumb_metacarpal_radius_per_hand_length",
    "thumb_proximal_radius_per_hand_length",
    "thumb_distal_radius_per_hand_length",
    "index_mcp_lateral_per_hand_breadth",
    "middle_mcp_lateral_per_hand_breadth",
    "ring_mcp_lateral_per_hand_breadth",
    "little_mcp_lateral_per_hand_breadth",
    "thumb_cmc_distal_per_hand_length",
    "thumb_cmc_palmar_per_hand_length",
    "thumb_cmc_radial_per_hand_length"};

TEST(ProportionTable, DefaultHasEveryNameTheModelNeeds) {
    const ProportionTable proportions = ProportionTable::loadHand();
    for (const char* name : kRequiredNames) {
        EXPECT_GT(proportions.get(name), 0.0) << name;
        EXPECT_LT(proportions.get(name), 1.0) << name;
    }
    EXPECT_EQ(proportions.getNames().size(), std::size(kRequiredNames));
}

TEST(ProportionTable, HandLengthPerStatureIsDrillisAndContini) {
    EXPECT_DOUBLE_EQ(ProportionTable::loadHand().get("hand_length_per_stature"), 0.108);
}

// Capsules taper distally and MCP joints lie left to right across the palm.
TEST(ProportionTable, DefaultValuesAreOrderedLikeAHand) {
    const ProportionTable p = ProportionTable::loadHand();
    EXPECT_GT(p.get("finger_proximal_radius_per_hand_length"),
              p.get("finger_middle_radius_per_hand_length"));
    EXPECT_GT(p.get("finger_middle_radius_per_hand_length"),
              p.get("finger_distal_radius_per_hand_length"));
    EXPECT_LT(p.get("index_mcp_lateral_per_hand_breadth"),
              p.get("middle_mcp_lateral_per_hand_breadth"));
    EXPECT_LT(p.get("ring_mcp_lateral_per_hand_breadth"),
              p.get("little_mcp_lateral_per_hand_breadth"));
}

TEST(ProportionTable, UnknownNameListsKnownNames) {
    const ProportionTable proportions = ProportionTable::loadHand();
    EXPECT_THAT([&] { proportions.get("palm_width"); },
                ThrowsMessage<InputError>(AllOf(
                    HasSubstr("anthropometry/hand_proportions.csv: proportion "
                              "'palm_width' is not known"),
                    HasSubstr("hand_length_per_stature, hand_breadth_per_hand_length"))));
}

TEST(ProportionTable, ParseCsvRejectsUnitsOtherThanRatio) {
    const std::string text = "name,value,unit,source\nhand_breadth,85,mm,measured\n";
    EXPECT_THAT([&] { ProportionTable::parseCsv(text, "h.csv"); },
                ThrowsMessage<InputError>(
                    StrEq("h.csv:2: field 'unit' value 'mm' is not accepted; use ratio")));
}

}  // namespace
}  // namespace graspsim::anthropometry

namespace graspsim::anthropometry {
namespace {

// The names the humanoid builder reads.
TEST(BodyProportions, DefaultHasEveryNameTheHumanoidNeeds) {
    const ProportionTable body = ProportionTable::loadBody();
    for (const char* name : {"shoulder_half_width_per_stature", "shoulder_below_suprasternale_per_stature",
                             "hip_half_width_per_stature", "ankle_from_heel_per_foot_length"}) {
        EXPECT_GT(body.get(name), 0.0) << name;
        EXPECT_LT(body.get(name), 1.0) << name;
    }
    EXPECT_EQ(body.getNames().size(), 4u);
}

}  // namespace
}  // namespace graspsim::anthropometry
