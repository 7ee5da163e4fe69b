#include "graspsim/contact/contact_force_law.h"

#include <gtest/gtest.h>

#include <cmath>

namespace graspsim::contact {
namespace {

ContactParameters makeParameters() {
    ContactParameters p;
    p.effectiveStiffness = 2e6;
    p.dissipation = 0.8;
    p.staticFriction = 0.9;
    p.dynamicFriction = 0.5;
    p.viscousFriction = 0.1;
    p.transitionVelocity = 0.01;
    return p;
}

TEST(ContactForceLaw, NormalForceAtRestIsHertz) {
    const ContactParameters p = makeParameters();
    const double R = 0.012, x = 0.0015;
    const double hertz = 4.0 / 3.0 * 2e6 * std::sqrt(0.012) * std::pow(0.0015, 1.5);
    EXPECT_NEAR(calcHertzForce(p, R, x), hertz, 1e-12 * hertz);
    EXPECT_NEAR(calcNormalForce(p, R, x, 0.0), hertz, 1e-12 * hertz);
    EXPECT_EQ(calcNormalForce(p, R, 0.0, 0.0), 0.0);
}

TEST(ContactForceLaw, ElasticEnergyIsTheIntegralOfTheHertzForce) {
    const ContactParameters p = makeParameters();
    const double R = 0.02, x = 0.002;
    EXPECT_NEAR(calcHertzEnergy(p, R, x), 8.0 / 15.0 * 2e6 * std::sqrt(R) * std::pow(x, 2.5),
                1e-15);
    // dU/dx = f_H (central difference).
    const double h = 1e-7;
    EXPECT_NEAR((calcHertzEnergy(p, R, x + h) - calcHertzEnergy(p, R, x - h)) / (2 * h),
                calcHertzForce(p, R, x), 1e-6 * calcHertzForce(p, R, x));
}

TEST(ContactForceLaw, DissipationAddsWhilePenetratingSubtractsWhileSeparatingNeverPulls) {
    const ContactParameters p = makeParameters();
    const double R = 0.01, x = 0.001, fH = calcHertzForce(p, R, x);
    EXPECT_NEAR(calcNormalForce(p, R, x, 0.2), fH * (1 + 1.5 * 0.8 * 0.2), 1e-12 * fH);
    EXPECT_NEAR(calcNormalForce(p, R, x, -0.2), fH * (1 - 1.5 * 0.8 * 0.2), 1e-12 * fH);
    // Separating faster than 1 / (1.5 c) = 0.833 m/s: Hunt-Crossley would pull; clamped to 0.
    EXPECT_EQ(calcNormalForce(p, R, x, -1.0), 0.0);
}

// The Stribeck formula written out once more, as the oracle.
double stribeck(double v) {
    const double r = v / 0.01;
    return std::min(r, 1.0) * (0.5 + 2 * (0.9 - 0.5) / (1 + r * r)) + 0.1 * v;
}

TEST(ContactForceLaw, FrictionCoefficientInEachRegime) {
    const ContactParameters p = makeParameters();
    // v << vt: linear rise with slope (2 mu_s - mu_d) / vt + mu_v to first order.
    EXPECT_NEAR(calcFrictionCoefficient(p, 1e-5), stribeck(1e-5), 1e-15);
    EXPECT_NEAR(calcFrictionCoefficient(p, 1e-5), 1e-5 / 0.01 * (2 * 0.9 - 0.5) + 0.1 * 1e-5, 1e-8);
    // v = vt: mu_d + (mu_s - mu_d) + mu_v vt = mu_s + mu_v vt.
    EXPECT_NEAR(calcFrictionCoefficient(p, 0.01), 0.9 + 0.1 * 0.01, 1e-15);
    // v >> vt: tends to mu_d + mu_v v.
    EXPECT_NEAR(calcFrictionCoefficient(p, 1.0), stribeck(1.0), 1e-15);
    EXPECT_NEAR(calcFrictionCoefficient(p, 1.0), 0.5 + 0.1 * 1.0, 1e-3);
    EXPECT_EQ(calcFrictionCoefficient(p, 0.0), 0.0);
}

TEST(ContactForceLaw, FrictionForceOpposesSlip) {
    const ContactParameters p = makeParameters();
    const SimTK::Vec3 slip(0.003, -0.004, 0);  // 5 mm/s
    const SimTK::Vec3 f = calcFrictionForce(p, 10.0, slip);
    const SimTK::Vec3 expected = -stribeck(0.005) * 10.0 * slip / 0.005;
    EXPECT_LE((f - expected).norm(), 1e-13);
    EXPECT_EQ(calcFrictionForce(p, 10.0, SimTK::Vec3(0)), SimTK::Vec3(0));
    EXPECT_EQ(calcFrictionForce(p, 0.0, slip), SimTK::Vec3(0));
}

}  // namespace
}  // namespace graspsim::contact
