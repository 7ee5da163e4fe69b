// The bounds: a record just inside passes, just outside fails, and each kind of run gets its
// own checks.

#include "graspsim/validation/validation_checks.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace graspsim;

namespace {

validation::RunRecord makeApproxRecord(double windowError) {
    validation::RunRecord r;
    r.run.id = "ball-clutch_none_approx-bushing-merged";
    r.run.reference = "ball-clutch_none_full";
    r.run.options.perturbation = "none";
    r.summary.complete = true;
    r.summary.engaged = true;
    r.summary.settleTime = 1.0;
    r.summary.engageTime = 1.0;
    r.summary.held = true;
    r.referenceHeld = true;
    r.hasReference = true;
    r.windowErrors.maxPosition = windowError;
    return r;
}

const validation::ValidationCheck& findCheck(const std::vector<validation::ValidationCheck>& checks, const std::string& start) {
    const auto it = std::find_if(checks.begin(), checks.end(), [&](const auto& c) { return c.name.rfind(start, 0) == 0; });
    if (it == checks.end()) throw std::runtime_error("no check " + start);
    return *it;
}

}  // namespace

TEST(ValidationChecks, PositionErrorBoundIsTwoMillimetres) {
    EXPECT_TRUE(findCheck(validation::checkRun(makeApproxRecord(0.00199)), "position error").pass);
    EXPECT_FALSE(findCheck(validation::checkRun(makeApproxRecord(0.00201)), "position error").pass);
}

TEST(ValidationChecks, VerdictMismatchFails) {
    validation::RunRecord r = makeApproxRecord(0);
    r.run.options.perturbation = "f1";
    r.summary.held = true;
    r.referenceHeld = false;
    const auto checks = validation::checkRun(r);
    EXPECT_FALSE(findCheck(checks, "hold/slide verdict").pass);
    // Under a perturbation the trajectories may legitimately differ: no pose-error bound.
    EXPECT_THROW(findCheck(checks, "position error"), std::runtime_error);
}

TEST(ValidationChecks, PenetrationGrowthBoundIsATenthOfAMillimetreForBothAttachments) {
    for (const auto attach : {simulation::ApproxAttach::Merged, simulation::ApproxAttach::Multi}) {
        validation::RunRecord r = makeApproxRecord(0);
        r.run.options.approx.attach = attach;
        r.summary.maxEngagedPenetrationGrowth = 0.00011;
        EXPECT_FALSE(findCheck(validation::checkRun(r), "fingertip penetration").pass);
        r.summary.maxEngagedPenetrationGrowth = 0.00009;
        EXPECT_TRUE(findCheck(validation::checkRun(r), "fingertip penetration").pass);
    }
}

TEST(ValidationChecks, PenetrationGrowthMayReachFullContactsOwnGrowthPlusATenth) {
    validation::RunRecord r = makeApproxRecord(0);
    r.referenceEngagedGrowth = 0.0003;
    r.summary.maxEngagedPenetrationGrowth = 0.00039;
    EXPECT_TRUE(findCheck(validation::checkRun(r), "fingertip penetration").pass);
    r.summary.maxEngagedPenetrationGrowth = 0.00041;
    EXPECT_FALSE(findCheck(validation::checkRun(r), "fingertip penetration").pass);
}

namespace {

simulation::ContactSample makeSample(double time, std::vector<std::pair<int, double>> depths) {
    simulation::ContactSample sample;
    sample.time = time;
    for (const auto& [pair, depth] : depths) {
        contact::ContactReport c;
        c.pairIndex = pair;
        c.depth = depth;
        sample.contacts.push_back(c);
    }
    return sample;
}

}  // namespace

// Growth of one pair beyond its own depth at the span's start; other pairs, and samples outside the
// span, do not count; a pair's deepest point counts.
TEST(ValidationChecks, DepthGrowthIsEachPairsOwnOverTheSpan) {
    const std::vector<simulation::ContactSample> contacts = {
        makeSample(0.9, {{1, 0.0010}, {2, 0.0020}}),
        makeSample(1.0, {{1, 0.0012}, {2, 0.0021}, {5, 0.0001}}),
        makeSample(1.1, {{1, 0.0015}, {1, 0.0016}, {2, 0.0020}, {5, 0.0030}}),
        makeSample(1.2, {{1, 0.0013}, {2, 0.0019}, {3, 0.0002}}),
        makeSample(1.3, {{1, 0.0050}}),
    };
    // Pair 1: 1.6 - 1.2 mm at 1.1 s; pair 3 enters at 1.2 s from nothing (0.2 mm).
    EXPECT_NEAR(validation::calcDepthGrowth(contacts, {1, 2, 3}, 1.0, 1.2), 0.0004, 1e-12);
    EXPECT_NEAR(validation::calcDepthGrowth(contacts, {2, 3}, 1.0, 1.2), 0.0002, 1e-12);
    // From 0.9 s, pair 2 grows by 0.1 mm before it shrinks.
    EXPECT_NEAR(validation::calcDepthGrowth(contacts, {2}, 0.9, 1.2), 0.0001, 1e-12);
    EXPECT_EQ(validation::calcDepthGrowth(contacts, {4}, 0.9, 1.3), 0.0);
    EXPECT_EQ(validation::calcDepthGrowth(contacts, {1}, 1.3, 2.0), 0.0);
}

TEST(ValidationChecks, EngagingBeforeSettlingFails) {
    validation::RunRecord r = makeApproxRecord(0);
    r.summary.engageTime = 0.9;
    EXPECT_FALSE(findCheck(validation::checkRun(r), "engaged after").pass);
}

TEST(ValidationChecks, FullRunHoldAndLongHoldDrift) {
    validation::RunRecord full;
    full.run.options.perturbation = "none";
    full.summary.complete = full.summary.held = true;
    full.summary.objectDisplacement = 0.006;
    EXPECT_FALSE(findCheck(validation::checkRun(full), "drift after settling").pass);
    full.summary.objectDisplacement = 0.004;
    EXPECT_TRUE(findCheck(validation::checkRun(full), "drift after settling").pass);
    validation::RunRecord hold = full;
    hold.run.longHold = true;
    EXPECT_FALSE(findCheck(validation::checkRun(hold), "long hold drift").pass);  // 4 mm > 1 mm
}
