#include <graspsim/anthropometry/sex.h>

#include <graspsim/error.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace graspsim::anthropometry {
namespace {

using ::testing::StrEq;
using ::testing::ThrowsMessage;

TEST(Sex, ParsesBothSpellings) {
    EXPECT_EQ(parseSex("female", "test"), Sex::Female);
    EXPECT_EQ(parseSex("male", "test"), Sex::Male);
}

TEST(Sex, ToStringRoundTrips) {
    for (Sex sex : {Sex::Female, Sex::Male}) EXPECT_EQ(parseSex(toString(sex), "test"), sex);
}

TEST(Sex, RejectsOtherTextNamingSourceAndValue) {
    EXPECT_THAT([] { parseSex("Male", "--sex"); },
                ThrowsMessage<InputError>(
                    StrEq("--sex: sex 'Male' is not accepted; use male or female")));
    EXPECT_THAT([] { parseSex("", "a.csv:3"); },
                ThrowsMessage<InputError>(
                    StrEq("a.csv:3: sex '' is not accepted; use male or female")));
}

}  // namespace
}  // namespace graspsim::anthropometry
