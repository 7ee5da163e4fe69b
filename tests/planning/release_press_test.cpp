// calcPressAfterRelease against closed forms of unilateral springs in equilibrium: two opposed
// fingers equalize their forces; a finger under the object carries its weight, e = m g / K; four
// fingers pressing as hard as one thumb push the object toward it until the weakest lets go, and
// the other three and the thumb then share the balance.

#include "graspsim/planning/release_press.h"

#include <gtest/gtest.h>

using graspsim::planning::calcPressAfterRelease;
using graspsim::planning::FingerPress;

namespace {

FingerPress makeFinger(SimTK::Vec3 p, SimTK::Vec3 n, double depth, double stiffness) {
    FingerPress f;
    f.p_GC = p;
    f.n_G = n;
    f.depth = depth;
    f.stiffness = stiffness;
    return f;
}

const SimTK::Vec3 kNoGravity(0, 0, 0);
// The twist no normal constrains is held by a thousandth of the normals' stiffness: it moves the
// balance by about that fraction of the presses (m).
constexpr double kTolerance = 1e-5;

}  // namespace

TEST(ReleasePress, TwoOpposedFingersEqualizeTheirForces) {
    // K1 (e1 - d) = K2 (e2 + d): d = (K1 e1 - K2 e2) / (K1 + K2)
    const double K1 = 1000, K2 = 3000, e1 = 0.004, e2 = 0.001;
    const std::vector<FingerPress> fingers{makeFinger({-0.02, 0, 0}, {1, 0, 0}, e1, K1),
                                           makeFinger({0.02, 0, 0}, {-1, 0, 0}, e2, K2)};
    const std::vector<double> press = calcPressAfterRelease(fingers, SimTK::Vec3(0), 0.1, kNoGravity);
    const double d = (K1 * e1 - K2 * e2) / (K1 + K2);
    EXPECT_NEAR(press[0], e1 - d, kTolerance);
    EXPECT_NEAR(press[1], e2 + d, kTolerance);
    EXPECT_NEAR(K1 * press[0], K2 * press[1], 3000 * kTolerance);
}

TEST(ReleasePress, AFingerUnderTheObjectCarriesItsWeight) {
    const double K = 2000, mass = 0.2, g = 9.81;
    const std::vector<FingerPress> fingers{makeFinger({0, -0.03, 0}, {0, 1, 0}, 0.002, K)};
    const std::vector<double> press = calcPressAfterRelease(fingers, SimTK::Vec3(0), mass, SimTK::Vec3(0, -g, 0));
    EXPECT_NEAR(press[0], mass * g / K, kTolerance);
}

TEST(ReleasePress, FourFingersPushTheObjectTowardTheThumbAndTheWeakestLetsGo) {
    // Thumb at -x pushing +x; four fingers at +x pushing -x, one of them pressing 0.5 mm. All
    // five pressing, the balance 2 + d = 3 (2 - d) + (0.5 - d) (mm) gives d = 0.9 mm, past the weak
    // finger's 0.5: it lets go, and 2 + d = 3 (2 - d) gives d = 1 mm, the others keep 1 mm.
    const double K = 1500, mm = 0.001;
    std::vector<FingerPress> fingers{makeFinger({-0.03, 0, 0}, {1, 0, 0}, 2 * mm, K)};
    for (double z : {-0.01, 0.0, 0.01}) fingers.push_back(makeFinger({0.03, 0, z}, {-1, 0, 0}, 2 * mm, K));
    fingers.push_back(makeFinger({0.03, 0.01, 0}, {-1, 0, 0}, 0.5 * mm, K));
    const std::vector<double> press = calcPressAfterRelease(fingers, SimTK::Vec3(0), 0.2, kNoGravity);
    EXPECT_NEAR(press[0], 3 * mm, kTolerance);
    for (int i = 1; i <= 3; ++i) EXPECT_NEAR(press[i], 1 * mm, kTolerance) << i;
    EXPECT_EQ(press[4], 0.0);
}
