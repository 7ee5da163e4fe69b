#include "graspsim/contact/contact_material.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "graspsim/error.h"

namespace graspsim::contact {
namespace {

std::string findValidationMessage(const ContactMaterial& material) {
    try {
        material.validate("hand material");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(ContactMaterial, PresetsAndDefaultsAreValid) {
    EXPECT_NO_THROW(ContactMaterial{}.validate("default"));
    EXPECT_NO_THROW(ContactMaterial::fingerPad().validate("skin"));
    EXPECT_NO_THROW(ContactMaterial::rigidPlastic().validate("plastic"));
}

TEST(ContactMaterial, NegativeFrictionIsRejectedWithFieldAndValue) {
    ContactMaterial m = ContactMaterial::fingerPad();
    m.staticFriction = -0.1;
    m.dynamicFriction = -0.2;
    EXPECT_EQ(findValidationMessage(m),
              "hand material: staticFriction (-0.1) must be finite and >= 0");
    m = ContactMaterial::fingerPad();
    m.viscousFriction = -3;
    EXPECT_EQ(findValidationMessage(m),
              "hand material: viscousFriction (-3) must be finite and >= 0 (s/m)");
}

TEST(ContactMaterial, NonPositiveStiffnessOrTransitionVelocityIsRejected) {
    ContactMaterial m;
    m.stiffness = -5e5;
    EXPECT_EQ(findValidationMessage(m),
              "hand material: stiffness (-500000) must be finite and > 0 (Pa)");
    m = ContactMaterial{};
    m.stiffness = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(findValidationMessage(m),
              "hand material: stiffness (nan) must be finite and > 0 (Pa)");
    m = ContactMaterial{};
    m.transitionVelocity = 0;
    EXPECT_EQ(findValidationMessage(m),
              "hand material: transitionVelocity (0) must be finite and > 0 (m/s)");
    m = ContactMaterial{};
    m.dissipation = -1;
    EXPECT_EQ(findValidationMessage(m),
              "hand material: dissipation (-1) must be finite and >= 0 (s/m)");
}

TEST(ContactMaterial, DynamicAboveStaticFrictionIsRejected) {
    ContactMaterial m;
    m.staticFriction = 0.5;
    m.dynamicFriction = 0.9;
    EXPECT_EQ(findValidationMessage(m),
              "hand material: dynamicFriction (0.9) is greater than staticFriction (0.5); it "
              "must be <= staticFriction");
}

}  // namespace
}  // namespace graspsim::contact
