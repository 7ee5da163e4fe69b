#include <graspsim/anthropometry/joint_ranges.h>

#include <graspsim/anthropometry/units.h>
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

const char* const kRequiredJoints[] = {
    "shoulder_flexion", "shoulder_abduction", "shoulder_rotation", "elbow_flexion",
    "forearm_pronation", "wrist_flexion", "wrist_deviation", "mcp_flexion", "mcp_abduction",
    "pip_flexion", "dip_flexion", "thumb_cmc_flexion", "thumb_cmc_abduction",
    "thumb_mcp_flexion", "thumb_ip_flexion", "neck_flexion", "neck_lateral", "neck_rotation",
    "lumbar_flexion", "lumbar_lateral", "lumbar_rotation", "thoracic_flexion",
    "thoracic_lateral", "thoracic_rotation", "hip_flexion", "hip_abduction", "hip_rotation",
    "knee_flexion", "ankle_flexion", "ankle_inversion"};

TEST(JointRanges, DefaultHasEveryJointWithLowerBelowUpper) {
    const JointRanges ranges = JointRanges::loadDefault();
    for (const char* joint : kRequiredJoints) {
        const JointRange& range = ranges.get(joint);
        EXPECT_LT(range.lower, range.upper) << joint;
        EXPECT_LE(range.lower, 0.0) << joint;  // the anatomical position is inside every range
        EXPECT_GE(range.upper, 0.0) << joint;
    }
    EXPECT_EQ(ranges.getJointNames().size(), std::size(kRequiredJoints));
}

TEST(JointRanges, DegreesAreConvertedToRadians) {
    const JointRanges ranges = JointRanges::loadDefault();
    EXPECT_DOUBLE_EQ(ranges.get("elbow_flexion").lower, 0.0);
    EXPECT_DOUBLE_EQ(ranges.get("elbow_flexion").upper, fromDegrees(150.0));
    EXPECT_DOUBLE_EQ(ranges.get("wrist_flexion").lower, fromDegrees(-70.0));
    EXPECT_DOUBLE_EQ(ranges.get("wrist_flexion").upper, fromDegrees(80.0));
}

// The thoracic and lumbar joints share the AAOS 1965 thoracolumbar ranges between them.
TEST(JointRanges, SpineSharesAddUpToTheThoracolumbarRange) {
    const JointRanges ranges = JointRanges::loadDefault();
    const auto total = [&](const std::string& motion) {
        const JointRange& lumbar = ranges.get("lumbar_" + motion);
        const JointRange& thoracic = ranges.get("thoracic_" + motion);
        return JointRange{lumbar.lower + thoracic.lower, lumbar.upper + thoracic.upper};
    };
    EXPECT_NEAR(total("flexion").lower, fromDegrees(-25.0), 1e-12);
    EXPECT_NEAR(total("flexion").upper, fromDegrees(80.0), 1e-12);
    EXPECT_NEAR(total("lateral").upper, fromDegrees(35.0), 1e-12);
    EXPECT_NEAR(total("rotation").upper, fromDegrees(45.0), 1e-12);
}

TEST(JointRanges, UnknownJointListsKnownJoints) {
    const JointRanges ranges = JointRanges::loadDefault();
    EXPECT_THAT([&] { ranges.get("elbow"); },
                ThrowsMessage<InputError>(AllOf(
                    HasSubstr("anthropometry/joint_ranges.csv: joint 'elbow' is not known"),
                    HasSubstr("shoulder_flexion, shoulder_abduction"))));
}

TEST(JointRanges, ParseCsvRejectsInvertedRanges) {
    const std::string text = "joint,lower_deg,upper_deg,source\nknee_flexion,135,0,test\n";
    EXPECT_THAT([&] { JointRanges::parseCsv(text, "j.csv"); },
                ThrowsMessage<InputError>(StrEq(
                    "j.csv:2: joint 'knee_flexion' lower_deg '135' is not accepted; it must be "
                    "less than upper_deg '0'")));
}

}  // namespace
}  // namespace graspsim::anthropometry
