#include "graspsim/io/number_text.h"

#include "graspsim/error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace {

using graspsim::io::parseNumber;
using graspsim::io::parsePositiveNumber;

std::string refusalOf(const std::string& text) {
    try {
        parsePositiveNumber(text, "--rate", "N/s");
    } catch (const graspsim::InputError& e) {
        return e.what();
    }
    return "";
}

// Oracle: the literal's own value, as the compiler reads it.
TEST(NumberText, TheWholeTextIsTheNumber) {
    EXPECT_EQ(parseNumber("2.5e-3", "--x", ""), 2.5e-3);
    EXPECT_EQ(parseNumber("-7", "--x", ""), -7.0);
    EXPECT_TRUE(std::isnan(parseNumber("nan", "--x", "")));
    EXPECT_EQ(parsePositiveNumber("0.125", "--rate", "N/s"), 0.125);
    EXPECT_FALSE(parsePositiveNumber("", "--rate", "N/s").has_value());
    EXPECT_EQ(graspsim::io::parseNonNegativeNumber("0", "--initial-load", "N"), 0.0);
    EXPECT_EQ(graspsim::io::parseNonNegativeNumber("", "--initial-load", "N"), 0.0);
    EXPECT_THROW(graspsim::io::parseNonNegativeNumber("-0.5", "--initial-load", "N"), graspsim::InputError);
}

TEST(NumberText, ARefusalNamesWhereTheValueCameFromAndWhatIsAccepted) {
    EXPECT_EQ(refusalOf("8 N"), "--rate: value '8 N' is not a number; a finite number > 0 (N/s)");
    EXPECT_EQ(refusalOf("0"), "--rate: value 0 is not accepted; use a finite number > 0 (N/s)");
    EXPECT_EQ(refusalOf("-1"), "--rate: value -1 is not accepted; use a finite number > 0 (N/s)");
    EXPECT_EQ(refusalOf("inf"), "--rate: value inf is not accepted; use a finite number > 0 (N/s)");
    EXPECT_EQ(refusalOf("nan"), "--rate: value nan is not accepted; use a finite number > 0 (N/s)");
}

}  // namespace
