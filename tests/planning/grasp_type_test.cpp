// Grasp type spellings: each parses back to itself; anything else is refused naming the value.

#include "graspsim/planning/grasp_type.h"

#include "graspsim/error.h"

#include <gtest/gtest.h>

using namespace graspsim;
using namespace graspsim::planning;

TEST(GraspType, EverySpellingParsesBackToItsType) {
    for (GraspType type : getGraspTypes()) EXPECT_EQ(parseGraspType(toString(type), "--type"), type);
    EXPECT_EQ(toString(GraspType::PowerSphere), "power-sphere");
}

TEST(GraspType, AnUnknownSpellingIsRefusedWithTheAcceptedOnes) {
    try {
        parseGraspType("power_sphere", "--type");
        FAIL() << "accepted";
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("--type value 'power_sphere'"), std::string::npos) << message;
        EXPECT_NE(message.find("power-sphere | pinch | tripod | power-cylinder | lateral"), std::string::npos) << message;
    }
}
