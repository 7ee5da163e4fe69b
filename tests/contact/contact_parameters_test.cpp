#include "graspsim/contact/contact_parameters.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "graspsim/error.h"

namespace graspsim::contact {
namespace {

std::string findValidationMessage(const ContactParameters& parameters) {
    try {
        parameters.validate("hand-object pair");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

// The defaults are the scenario file's (models/scenarios/ball-clutch.yaml documents them): a
// default-constructed pair is what a scenario without a contact section simulates.
TEST(ContactParameters, DefaultsAreTheScenarioFilesAndValid) {
    const ContactParameters p;
    EXPECT_EQ(p.effectiveStiffness, 5e5);
    EXPECT_EQ(p.dissipation, 0.8);
    EXPECT_EQ(p.staticFriction, 0.9);
    EXPECT_EQ(p.dynamicFriction, 0.7);
    EXPECT_EQ(p.viscousFriction, 0);
    EXPECT_EQ(p.transitionVelocity, 1e-3);
    EXPECT_NO_THROW(p.validate("default"));
}

TEST(ContactParameters, NegativeFrictionIsRejectedWithFieldAndValue) {
    ContactParameters p;
    p.staticFriction = -0.1;
    p.dynamicFriction = -0.2;
    EXPECT_EQ(findValidationMessage(p),
              "hand-object pair: staticFriction (-0.1) must be finite and >= 0");
    p = ContactParameters{};
    p.viscousFriction = -3;
    EXPECT_EQ(findValidationMessage(p),
              "hand-object pair: viscousFriction (-3) must be finite and >= 0 (s/m)");
}

TEST(ContactParameters, NonPositiveStiffnessOrTransitionVelocityIsRejected) {
    ContactParameters p;
    p.effectiveStiffness = -5e5;
    EXPECT_EQ(findValidationMessage(p),
              "hand-object pair: effectiveStiffness (-500000) must be finite and > 0 (Pa)");
    p = ContactParameters{};
    p.effectiveStiffness = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(findValidationMessage(p),
              "hand-object pair: effectiveStiffness (nan) must be finite and > 0 (Pa)");
    p = ContactParameters{};
    p.transitionVelocity = 0;
    EXPECT_EQ(findValidationMessage(p),
              "hand-object pair: transitionVelocity (0) must be finite and > 0 (m/s)");
    p = ContactParameters{};
    p.dissipation = -1;
    EXPECT_EQ(findValidationMessage(p),
              "hand-object pair: dissipation (-1) must be finite and >= 0 (s/m)");
}

TEST(ContactParameters, DynamicAboveStaticFrictionIsRejected) {
    ContactParameters p;
    p.staticFriction = 0.5;
    p.dynamicFriction = 0.9;
    EXPECT_EQ(findValidationMessage(p),
              "hand-object pair: dynamicFriction (0.9) is greater than staticFriction (0.5); it "
              "must be <= staticFriction");
    p.dynamicFriction = 0.5;  // equal is accepted (Coulomb friction without a static peak)
    EXPECT_NO_THROW(p.validate("equal"));
}

}  // namespace
}  // namespace graspsim::contact
