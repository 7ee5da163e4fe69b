#include "graspsim/model/object_model.h"

#include "graspsim/error.h"

#include <gtest/gtest.h>

using namespace graspsim::model;

TEST(ObjectModel, BallIsAUniformSphereOfTheThesisMass) {
    const ModelDescription ball = buildBallModel();
    const Body& b = ball.bodies.at(0);
    EXPECT_DOUBLE_EQ(b.mass, 0.200);
    EXPECT_NEAR(b.inertia.xx, 0.4 * 0.200 * kBallRadius * kBallRadius, 1e-15);
    EXPECT_EQ(b.geometry.at(0).type, Geometry::Type::Sphere);
}

TEST(ObjectModel, PhoneIsAUniformBoxOfTheThesisMassAndSize) {
    const ModelDescription phone = buildPhoneModel();
    const Body& b = phone.bodies.at(0);
    EXPECT_DOUBLE_EQ(b.mass, 0.100);
    const double w = 0.07, l = 0.14, t = 0.008;
    EXPECT_NEAR(b.inertia.xx, 0.1 * (l * l + t * t) / 12, 1e-15);
    EXPECT_NEAR(b.inertia.yy, 0.1 * (w * w + t * t) / 12, 1e-15);
    EXPECT_NEAR(b.inertia.zz, 0.1 * (w * w + l * l) / 12, 1e-15);
}

TEST(ObjectModel, UnknownObjectIsNamed) {
    try {
        buildObjectModel("cube", "object name");
        FAIL();
    } catch (const graspsim::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("'cube'"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("ball or phone"), std::string::npos);
    }
}
