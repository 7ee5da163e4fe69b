// Trajectory comparison against hand-computed errors: a constant offset, a known rotation, and
// a slip onset at a known sample.

#include "graspsim/validation/trajectory_comparison.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace graspsim;

namespace {

simulation::TrajectorySample makeSample(double t, const SimTK::Vec3& p, const SimTK::Quaternion& q = SimTK::Quaternion()) {
    simulation::TrajectorySample s;
    s.time = t;
    s.p_GO = p;
    s.q_GO = q;
    return s;
}

}  // namespace

TEST(TrajectoryComparison, ConstantOffsetGivesEqualMaxAndRms) {
    std::vector<simulation::TrajectorySample> reference, candidate;
    for (int k = 0; k <= 10; ++k) {
        reference.push_back(makeSample(0.1 * k, SimTK::Vec3(0.1 * k, 0, 0)));
        candidate.push_back(makeSample(0.1 * k, SimTK::Vec3(0.1 * k, 0.003, 0.004)));
    }
    const validation::PoseErrors e = validation::comparePoses(reference, candidate, 0.25, 0.75);
    EXPECT_EQ(e.samples, 5);  // 0.3 ... 0.7
    EXPECT_NEAR(e.maxPosition, 0.005, 1e-15);
    EXPECT_NEAR(e.rmsPosition, 0.005, 1e-15);
    EXPECT_NEAR(e.maxAngle, 0, 1e-12);
}

TEST(TrajectoryComparison, RmsOfARampAndMissingSamplesAreSkipped) {
    std::vector<simulation::TrajectorySample> reference, candidate;
    for (int k = 0; k < 4; ++k) {
        reference.push_back(makeSample(k, SimTK::Vec3(0)));
        if (k != 2) candidate.push_back(makeSample(k, SimTK::Vec3(0, 0, 0.001 * k)));  // 0, 1, 3 mm
    }
    const validation::PoseErrors e = validation::comparePoses(reference, candidate, 0, 3);
    EXPECT_EQ(e.samples, 3);
    EXPECT_NEAR(e.maxPosition, 0.003, 1e-15);
    EXPECT_NEAR(e.rmsPosition, std::sqrt((0.0 + 1e-6 + 9e-6) / 3), 1e-15);
}

TEST(TrajectoryComparison, AngleOfAKnownRotationIgnoringQuaternionSign) {
    const SimTK::Rotation R(0.3, SimTK::UnitVec3(1, 2, 3));
    const SimTK::Quaternion q = R.convertRotationToQuaternion();
    const SimTK::Quaternion minusQ(-q.asVec4(), true);
    EXPECT_NEAR(validation::calcRotationAngle(SimTK::Quaternion(), q), 0.3, 1e-12);
    EXPECT_NEAR(validation::calcRotationAngle(SimTK::Quaternion(), minusQ), 0.3, 1e-12);
    std::vector<simulation::TrajectorySample> a{makeSample(0, SimTK::Vec3(0))}, b{makeSample(0, SimTK::Vec3(0), q)};
    EXPECT_NEAR(validation::comparePoses(a, b, 0, 0).maxAngle, 0.3, 1e-12);
}

TEST(TrajectoryComparison, SlipOnsetIsTheFirstSampleBeyondTheDistanceAfterSettling) {
    std::vector<simulation::TrajectorySample> t;
    for (int k = 0; k <= 30; ++k) t.push_back(makeSample(0.1 * k, SimTK::Vec3(0, k < 10 ? 0.5 : -0.001 * (k - 10), 0)));
    // Settled at 1.0 s (k = 10): 2 mm is exceeded at k = 13 (3 mm).
    EXPECT_NEAR(validation::findSlipOnset(t, 1.0, 0.0025), 1.3, 1e-12);
    EXPECT_EQ(validation::findSlipOnset(t, 1.0, 0.1), -1);
    EXPECT_EQ(validation::findSlipOnset(t, 5.0, 0.001), -1);
}
