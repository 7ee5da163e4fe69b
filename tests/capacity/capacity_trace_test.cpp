#include "graspsim/capacity/capacity_trace.h"

#include "graspsim/error.h"

#include <gtest/gtest.h>

#include <cmath>

using graspsim::capacity::CapacitySample;
using graspsim::capacity::checkSlipCriteria;
using graspsim::capacity::findCapacityFigures;
using graspsim::capacity::SlipCriteria;

namespace {

CapacitySample makeSample(double time, double load, double slip, bool held = true) {
    CapacitySample s;
    s.time = time;
    s.load = load;
    s.slip = slip;
    s.held = held;
    return s;
}

}  // namespace

// Slip growing as (t - 1)^2 for t > 1 under a load 10 t: onset where (t - 1)^2 = 2 mm, drop where
// it reaches 20 mm. Between samples the slip is interpolated linearly, so with 1 ms samples the
// crossing times are exact to the chord's error (< 1e-4 s here).
TEST(CapacityTrace, SlipOnsetAndDropAreTheThresholdCrossings) {
    std::vector<CapacitySample> samples;
    for (int k = 0; k <= 2000; ++k) {
        const double t = 1e-3 * k;
        samples.push_back(makeSample(t, 10 * t, t > 1 ? (t - 1) * (t - 1) : 0.0));
    }
    const auto f = findCapacityFigures(samples, SlipCriteria{});
    ASSERT_TRUE(f.slipped);
    ASSERT_TRUE(f.dropped);
    EXPECT_NEAR(f.slipOnsetTime, 1 + std::sqrt(0.002), 1e-4);
    EXPECT_NEAR(f.slipOnsetLoad, 10 * (1 + std::sqrt(0.002)), 1e-3);
    EXPECT_NEAR(f.dropTime, 1 + std::sqrt(0.02), 1e-4);
    EXPECT_NEAR(f.dropLoad, 10 * (1 + std::sqrt(0.02)), 1e-3);
}

TEST(CapacityTrace, NoSlipBelowTheThreshold) {
    const std::vector<CapacitySample> samples{makeSample(0, 0, 0), makeSample(1, 5, 0.0019)};
    const auto f = findCapacityFigures(samples, SlipCriteria{});
    EXPECT_FALSE(f.slipped);
    EXPECT_FALSE(f.dropped);
}

// A grasp that lets go (held false) drops there, and counts as slipped at that load if it had not.
TEST(CapacityTrace, LosingTheGraspIsADrop) {
    const std::vector<CapacitySample> samples{makeSample(0, 0, 0), makeSample(1, 5, 0.001), makeSample(2, 10, 0.0015, false)};
    const auto f = findCapacityFigures(samples, SlipCriteria{});
    ASSERT_TRUE(f.dropped);
    EXPECT_EQ(f.dropLoad, 10);
    EXPECT_EQ(f.dropTime, 2);
    ASSERT_TRUE(f.slipped);
    EXPECT_EQ(f.slipOnsetLoad, 10);
}

// The approximation's release is the first sample where it is no longer engaged.
TEST(CapacityTrace, TheReleaseIsTheFirstSampleNoLongerEngaged) {
    std::vector<CapacitySample> samples{makeSample(0, 0, 0), makeSample(1, 5, 0.001), makeSample(2, 10, 0.001),
                                        makeSample(3, 15, 0.001)};
    samples[0].engaged = samples[1].engaged = 1;
    samples[2].engaged = 0;
    samples[3].engaged = 1;  // engaged again: not a second first release
    const auto f = findCapacityFigures(samples, SlipCriteria{});
    ASSERT_TRUE(f.released);
    EXPECT_EQ(f.releaseLoad, 10);
    EXPECT_EQ(f.releaseTime, 2);
    samples[2].engaged = -1;  // full mode: no approximation, nothing released
    samples[0].engaged = samples[1].engaged = samples[3].engaged = -1;
    EXPECT_FALSE(findCapacityFigures(samples, SlipCriteria{}).released);
}

// A step handed back at once: the first sample (the load's start) is already released.
TEST(CapacityTrace, AFirstSampleNoLongerEngagedIsAReleaseAtTheStart) {
    std::vector<CapacitySample> samples{makeSample(1, 8, 0), makeSample(1.001, 8, 0.0005)};
    samples[0].engaged = samples[1].engaged = 0;
    const auto f = findCapacityFigures(samples, SlipCriteria{});
    ASSERT_TRUE(f.released);
    EXPECT_EQ(f.releaseTime, 1);
    EXPECT_EQ(f.releaseLoad, 8);
}

// The grip force is read at the load's start and, at the slip onset, interpolated as the load is:
// linear in time here (20 + 5 t N), so at the onset it is 20 + 5 t_onset to rounding. A grip not measured on
// either side of the crossing (NaN: the approximation engaged there) stays unmeasured.
TEST(CapacityTrace, GripForceAtTheStartAndInterpolatedAtTheOnset) {
    std::vector<CapacitySample> samples;
    for (int k = 0; k <= 2000; ++k) {
        const double t = 1e-3 * k;
        samples.push_back(makeSample(t, 10 * t, t > 1 ? (t - 1) * (t - 1) : 0.0));
        samples.back().gripForce = 20 + 5 * t;
    }
    const auto f = findCapacityFigures(samples, SlipCriteria{});
    EXPECT_DOUBLE_EQ(f.gripForceAtStart, 20);
    EXPECT_NEAR(f.gripForceAtOnset, 20 + 5 * f.slipOnsetTime, 1e-9);

    // Engaged until just after the onset's crossing: the onset's grip is not measured.
    for (CapacitySample& s : samples) {
        if (s.time <= 1 + std::sqrt(0.002)) s.gripForce = std::nan("");
    }
    const auto engaged = findCapacityFigures(samples, SlipCriteria{});
    EXPECT_TRUE(std::isnan(engaged.gripForceAtStart));
    EXPECT_TRUE(std::isnan(engaged.gripForceAtOnset));
    EXPECT_NEAR(engaged.slipOnsetLoad, f.slipOnsetLoad, 1e-12);
}

// The slip onset must come before the drop: just below is accepted, equal or above is refused
// naming the source and value given, with the distance left at its default called so.
TEST(CapacityTrace, TheSlipOnsetMustComeBeforeTheDrop) {
    const auto refusal = [](const SlipCriteria& criteria) {
        try {
            checkSlipCriteria(criteria, "--slip-threshold", "given");
        } catch (const graspsim::InputError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_EQ(refusal(SlipCriteria{}), "accepted");
    EXPECT_EQ(refusal({0.0199, 0.02}), "accepted");
    EXPECT_EQ(refusal({0.02, 0.02}),
              "--slip-threshold: value given is not accepted; the slip threshold (0.02 m) must be below the drop threshold (0.02 m, the default)");
    EXPECT_EQ(refusal({0.002, 0.001}),
              "--slip-threshold: value given is not accepted; the slip threshold (0.002 m, the default) must be below the drop threshold (0.001 m)");
}
