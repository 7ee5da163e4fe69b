#include "graspsim/capacity/load_direction.h"

#include "graspsim/error.h"

#include <gtest/gtest.h>

#include <cmath>

using graspsim::capacity::parseLoadDirection;

TEST(LoadDirection, AxesAndVectors) {
    EXPECT_EQ(parseLoadDirection("-y", "--direction").direction, SimTK::UnitVec3(0, -1, 0));
    EXPECT_EQ(parseLoadDirection("z", "--direction").direction, SimTK::UnitVec3(0, 0, 1));
    const SimTK::UnitVec3 d = parseLoadDirection("3,0,-4", "--direction").direction;
    EXPECT_NEAR(d[0], 0.6, 1e-15);
    EXPECT_NEAR(d[2], -0.8, 1e-15);
    EXPECT_EQ(parseLoadDirection("0 1 0", "--direction").direction, SimTK::UnitVec3(0, 1, 0));
    EXPECT_EQ(graspsim::capacity::findAxisDirections().size(), 6u);
    // Only the direction counts, however large or small the numbers: the norm would overflow or underflow.
    const SimTK::UnitVec3 huge = parseLoadDirection("1e200,-1e200,0", "--direction").direction;
    EXPECT_NEAR(huge[0], std::sqrt(0.5), 1e-15);
    EXPECT_NEAR(huge[1], -std::sqrt(0.5), 1e-15);
    EXPECT_EQ(parseLoadDirection("0,0,-1e-300", "--direction").direction, SimTK::UnitVec3(0, 0, -1));
}

TEST(LoadDirection, RejectsWhatIsNotADirection) {
    for (const char* text : {"up", "0,0,0", "1,2", "1,2,3,4", "nan,0,1", "inf,0,0", ""}) {
        try {
            parseLoadDirection(text, "--direction");
            ADD_FAILURE() << text;
        } catch (const graspsim::InputError& e) {
            EXPECT_NE(std::string(e.what()).find("--direction"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("-x"), std::string::npos) << e.what();
        }
    }
}
