#include <graspsim/anthropometry/subject.h>

#include <graspsim/error.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>

namespace graspsim::anthropometry {
namespace {

using ::testing::HasSubstr;
using ::testing::StrEq;
using ::testing::ThrowsMessage;

TEST(Subject, ReferenceSubjectsAreDeLevas) {
    const Subject female = getReferenceSubject(Sex::Female);
    EXPECT_EQ(female.sex, Sex::Female);
    EXPECT_DOUBLE_EQ(female.mass, 61.9);
    EXPECT_DOUBLE_EQ(female.stature, 1.735);
    const Subject male = getReferenceSubject(Sex::Male);
    EXPECT_EQ(male.sex, Sex::Male);
    EXPECT_DOUBLE_EQ(male.mass, 73.0);
    EXPECT_DOUBLE_EQ(male.stature, 1.741);
}

// The defaults in subject.h copy the male reference row; this pins the copy to the CSV.
TEST(Subject, DefaultIsTheMaleReferenceSubject) {
    const Subject defaults;
    const Subject reference = getReferenceSubject(Sex::Male);
    EXPECT_EQ(defaults.sex, reference.sex);
    EXPECT_DOUBLE_EQ(defaults.mass, reference.mass);
    EXPECT_DOUBLE_EQ(defaults.stature, reference.stature);
}

TEST(Subject, ValidateAcceptsReferenceSubjectsAndRangeEnds) {
    EXPECT_NO_THROW(validateSubject(getReferenceSubject(Sex::Female), "test"));
    EXPECT_NO_THROW(validateSubject(getReferenceSubject(Sex::Male), "test"));
    EXPECT_NO_THROW(validateSubject(Subject{Sex::Male, 20.0, 1.0}, "test"));
    EXPECT_NO_THROW(validateSubject(Subject{Sex::Female, 250.0, 2.5}, "test"));
}

TEST(Subject, ValidateRejectsBadMassNamingTheField) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THAT([&] { validateSubject(Subject{Sex::Male, nan, 1.741}, "scenario.json"); },
                ThrowsMessage<InputError>(StrEq(
                    "scenario.json: field 'mass' value nan is not accepted; body mass must be "
                    "a finite number in [20, 250] kg")));
    for (double mass : {0.0, -73.0, 1000.0, std::numeric_limits<double>::infinity()}) {
        EXPECT_THAT([&] { validateSubject(Subject{Sex::Male, mass, 1.741}, "scenario.json"); },
                    ThrowsMessage<InputError>(HasSubstr("scenario.json: field 'mass' value ")))
            << mass;
    }
}

TEST(Subject, ValidateRejectsBadStatureNamingTheField) {
    EXPECT_THAT([] { validateSubject(Subject{Sex::Female, 61.9, 0.3}, "scenario.json"); },
                ThrowsMessage<InputError>(StrEq(
                    "scenario.json: field 'stature' value 0.3 is not accepted; stature must be "
                    "a finite number in [1, 2.5] m")));
}

TEST(Subject, SingleValueChecksNameTheFlag) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THAT([&] { validateBodyMass(nan, "--mass"); },
                ThrowsMessage<InputError>(StrEq(
                    "--mass: value nan is not accepted; body mass must be a finite number in "
                    "[20, 250] kg")));
    EXPECT_THAT([] { validateStature(1741.0, "--stature"); },
                ThrowsMessage<InputError>(StrEq(
                    "--stature: value 1741 is not accepted; stature must be a finite number "
                    "in [1, 2.5] m")));
    EXPECT_NO_THROW(validateBodyMass(73.0, "--mass"));
    EXPECT_NO_THROW(validateStature(1.741, "--stature"));
}

}  // namespace
}  // namespace graspsim::anthropometry
