// --release-at compliance (ApproxReleaseTrigger::Compliance): the approximation keeps the thesis's
// box as its limits and hands the object back to full contact once the constraint's reaction
// reaches the grasp's compliance-model limit on an axis side. Oracle: the full-contact run of the
// same scenario (the second method), and, where the trigger never fires, the run without it.
#include "graspsim/simulation/grasp_simulation.h"
#include "graspsim/simulation/compliance_release.h"
#include "graspsim/simulation/grasp_switch.h"
#include "graspsim/simulation/simulation_options.h"
#include "graspsim/error.h"
#include "graspsim/scenario/scenario_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

using namespace graspsim;

namespace {

simulation::SimulationOptions makeOptions(simulation::SimulationMode mode, const std::string& perturbation, bool release) {
    simulation::SimulationOptions options;
    options.mode = mode;
    options.perturbation = perturbation;
    options.approx.releaseTrigger = release ? simulation::ApproxReleaseTrigger::Compliance : simulation::ApproxReleaseTrigger::None;
    return options;
}

// Largest distance (m) between the two runs' objects at their common sample times.
double findLargestDistance(const simulation::SimulationResult& a, const simulation::SimulationResult& b) {
    EXPECT_EQ(a.trajectory.size(), b.trajectory.size());
    double worst = 0;
    for (std::size_t k = 0; k < std::min(a.trajectory.size(), b.trajectory.size()); ++k) {
        worst = std::max(worst, (a.trajectory[k].p_GO - b.trajectory[k].p_GO).norm());
    }
    return worst;
}

// phone-pinch approached for 0.05 s and settled for 0.15 s (instead of 0.5 s and 1.0 s): the
// switch's first full-contact check comes while the pads are still taking up the phone's weight.
scenario::Scenario makeUnsettledPhone() {
    std::ifstream in(std::filesystem::path(GRASPSIM_SOURCE_DIR) / "models/scenarios/phone-pinch.yaml");
    std::stringstream buffer;
    buffer << in.rdbuf();
    std::string text = buffer.str();
    for (const auto& [from, to] : {std::pair<std::string, std::string>{"approach_time: 0.5 ", "approach_time: 0.05"},
                                   {"settle_time: 1.0 ", "settle_time: 0.15"}}) {
        const std::size_t at = text.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        if (at != std::string::npos) text.replace(at, from.size(), to);
    }
    return scenario::parseScenario(text, "unsettled-phone.yaml");
}

// The direction model of a stiff pinch: contacts at x = -2 cm and +2 cm, each pressing with
// `N` (N), friction `mu` breaking loose and sliding; the sides are left to the test.
simulation::ComplianceReleaseLimits makeStiffPinch(double mu, double N) {
    const double d = 0.02;
    simulation::ComplianceReleaseLimits limits;
    for (double side : {-1.0, 1.0}) {
        grasp::CompliantContact c;
        c.p_GC = Eigen::Vector3d(side * d, 0, 0);
        c.n_G = Eigen::Vector3d(-side, 0, 0);
        c.force_G = N * c.n_G;
        c.normalStiffness = 4e5;
        c.tangentialStiffness = 4e5;
        c.fingerCompliance_G = 1e-6 * Eigen::Matrix3d::Identity();
        limits.contacts_O.push_back(c);
    }
    limits.mu = limits.kineticMu = mu;
    return limits;
}

}  // namespace

// Engaged at its first check (0.22 s), the unsettled phone's weight was outside the limits of that
// state and the trigger handed it back 0.13 ms later, for good. The switch now engages only once
// the held wrench is inside the limits it would engage with (as after a release), and the
// approximated phone then stays with full contact's: within the must-show's 2 mm (measured 1.23 mm).
TEST(GraspSwitchRelease, UnsettledGraspEngagesOnlyInsideItsLimitsAndStaysWithFullContact) {
    const scenario::Scenario s = makeUnsettledPhone();
    simulation::SimulationOptions full = makeOptions(simulation::SimulationMode::Full, "none", false);
    simulation::SimulationOptions approx = makeOptions(simulation::SimulationMode::Approx, "none", true);
    full.duration = approx.duration = 1.5;
    const auto fullRun = simulation::runGraspSimulation(s, full);
    const auto approxRun = simulation::runGraspSimulation(s, approx);
    ASSERT_TRUE(approxRun.summary.complete) << approxRun.summary.failure;
    ASSERT_EQ(approxRun.events.size(), 1u) << approxRun.events.back().reason;
    EXPECT_EQ(approxRun.events[0].kind, simulation::GraspEventKind::Engage);
    EXPECT_TRUE(approxRun.summary.held);
    const double gap = findLargestDistance(approxRun, fullRun);
    EXPECT_LT(gap, 0.002) << "approx object " << gap << " m from the full-contact object";
}

// Ball f1 pushes the ball along -y (the bushing's reaction peaks at 11.6 N), which full contact
// holds, below the compliance model's side for it (13.45 N since the tangential stiffness is
// shared by normal force; Hertz-Mindlin's sharing gave 11.12 N and released during the push):
// the approximation holds the ball through the push, and the
// object stays within 2 mm of full contact's over the whole run (the must-show's bound; measured
// 1.23 mm, the thesis's box's figure: the bushing's missing give).
TEST(GraspSwitchRelease, BallF1StaysEngagedAndWithFullContact) {
    const scenario::Scenario s = scenario::findBuiltinScenario("ball-clutch");
    const auto full = simulation::runGraspSimulation(s, makeOptions(simulation::SimulationMode::Full, "f1", false));
    const auto approx = simulation::runGraspSimulation(s, makeOptions(simulation::SimulationMode::Approx, "f1", true));
    ASSERT_TRUE(full.summary.complete) << full.summary.failure;
    ASSERT_TRUE(approx.summary.complete) << approx.summary.failure;
    for (const simulation::GraspEvent& e : approx.events) {
        EXPECT_NE(e.kind, simulation::GraspEventKind::Release) << "released at " << e.time << " s: " << e.reason;
    }
    EXPECT_EQ(approx.summary.held, full.summary.held);
    const double gap = findLargestDistance(approx, full);
    EXPECT_LT(gap, 0.002) << "approx object " << gap << " m from the full-contact object";
}

// Without a perturbation nothing reaches the model's limits: the switch engages once, never
// releases, and the run is the one without the trigger sample for sample (the trigger only reads).
TEST(GraspSwitchRelease, UnperturbedRunIsTheRunWithoutTheTrigger) {
    for (const std::string name : {"ball-clutch", "phone-pinch"}) {
        SCOPED_TRACE(name);
        const scenario::Scenario s = scenario::findBuiltinScenario(name);
        const auto plain = simulation::runGraspSimulation(s, makeOptions(simulation::SimulationMode::Approx, "none", false));
        const auto watched = simulation::runGraspSimulation(s, makeOptions(simulation::SimulationMode::Approx, "none", true));
        ASSERT_TRUE(watched.summary.complete) << watched.summary.failure;
        ASSERT_EQ(watched.events.size(), 1u) << watched.events.back().reason;
        EXPECT_NE(watched.events[0].reason.find("release at compliance limits"), std::string::npos);
        ASSERT_EQ(plain.trajectory.size(), watched.trajectory.size());
        for (std::size_t k = 0; k < plain.trajectory.size(); ++k) {
            ASSERT_EQ(plain.trajectory[k].p_GO, watched.trajectory[k].p_GO) << "t = " << plain.trajectory[k].time;
        }
    }
}

TEST(GraspSwitchRelease, ParsesAndRefusesOtherAttachments) {
    EXPECT_EQ(simulation::parseApproxReleaseTrigger("none", "--release-at"), simulation::ApproxReleaseTrigger::None);
    EXPECT_EQ(simulation::parseApproxReleaseTrigger("compliance", "--release-at"), simulation::ApproxReleaseTrigger::Compliance);
    EXPECT_THROW(simulation::parseApproxReleaseTrigger("slip", "--release-at"), InputError);
    const scenario::Scenario s = scenario::findBuiltinScenario("ball-clutch");
    simulation::SimulationOptions options = makeOptions(simulation::SimulationMode::Approx, "none", true);
    EXPECT_NO_THROW(simulation::checkApproxAttach(s, options));
    options.approx.constraint = simulation::ApproxConstraint::Weld;
    try {
        simulation::checkApproxAttach(s, options);
        ADD_FAILURE() << "weld accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("--release-at"), std::string::npos) << e.what();
    }
    options.approx.constraint = simulation::ApproxConstraint::Bushing;
    options.approx.attach = simulation::ApproxAttach::Multi;
    EXPECT_THROW(simulation::checkApproxAttach(s, options), InputError);
    options.mode = simulation::SimulationMode::Full;  // full contact ignores the approximation's options
    EXPECT_NO_THROW(simulation::checkApproxAttach(s, options));
}

// The default: the trigger on the merged bushing, the thesis's switch on the weld and multi (which
// the compliance trigger does not take); an explicit choice is kept.
TEST(GraspSwitchRelease, AutomaticIsComplianceOnTheMergedBushingOnly) {
    EXPECT_EQ(simulation::parseApproxReleaseTrigger("auto", "--release-at"), simulation::ApproxReleaseTrigger::Automatic);
    EXPECT_EQ(simulation::ApproxOptions{}.releaseTrigger, simulation::ApproxReleaseTrigger::Automatic);
    const scenario::ApproximationSpec spec;
    simulation::ApproxOptions options;
    EXPECT_EQ(simulation::resolveApproxOptions(options, spec).releaseTrigger, simulation::ApproxReleaseTrigger::Compliance);
    options.constraint = simulation::ApproxConstraint::Weld;
    EXPECT_EQ(simulation::resolveApproxOptions(options, spec).releaseTrigger, simulation::ApproxReleaseTrigger::None);
    options.constraint = simulation::ApproxConstraint::Bushing;
    options.attach = simulation::ApproxAttach::Multi;
    EXPECT_EQ(simulation::resolveApproxOptions(options, spec).releaseTrigger, simulation::ApproxReleaseTrigger::None);
    options.attach = simulation::ApproxAttach::Merged;
    options.releaseTrigger = simulation::ApproxReleaseTrigger::None;
    EXPECT_EQ(simulation::resolveApproxOptions(options, spec).releaseTrigger, simulation::ApproxReleaseTrigger::None);
}

// The deflected hand-back is opt-in and needs the compliance trigger, which resolves from auto on
// the merged bushing only.
TEST(GraspSwitchRelease, DeflectedHandBackNeedsTheComplianceTrigger) {
    EXPECT_EQ(simulation::parseApproxHandBack("deflected", "--hand-back"), simulation::ApproxHandBack::Deflected);
    EXPECT_EQ(simulation::ApproxOptions{}.handBack, simulation::ApproxHandBack::Engaged);
    EXPECT_THROW(simulation::parseApproxHandBack("bent", "--hand-back"), InputError);
    const scenario::ApproximationSpec spec;
    simulation::ApproxOptions options;
    options.handBack = simulation::ApproxHandBack::Deflected;
    EXPECT_NO_THROW(simulation::resolveApproxOptions(options, spec));
    options.constraint = simulation::ApproxConstraint::Weld;
    try {
        simulation::resolveApproxOptions(options, spec);
        ADD_FAILURE() << "deflected hand-back accepted on the weld";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("--hand-back"), std::string::npos) << e.what();
    }
}

// The inside test of the engage rule and the trigger, on a hand-made wrench: a side is reached
// at its own limit (the upper for a positive component, the lower for a negative one).
TEST(GraspSwitchRelease, FindAxisAtLimitUsesEachSide) {
    simulation::ComplianceReleaseLimits limits;
    limits.lower = SimTK::Vec6(1, 1, 1, 8, 8, 8);
    limits.upper = SimTK::Vec6(1, 1, 1, 6, 11, 7);
    EXPECT_TRUE(simulation::findAxisAtLimit(SimTK::Vec6(0, 0, 0, 5.9, -7.9, 6.9), limits).empty());
    const std::string x = simulation::findAxisAtLimit(SimTK::Vec6(0, 0, 0, 6.1, 0, 0), limits);
    EXPECT_NE(x.find("translation x 6.1 N reached the compliance limit 6 N"), std::string::npos) << x;
    const std::string y = simulation::findAxisAtLimit(SimTK::Vec6(0, 0, 0, 0, -8.2, 0), limits);
    EXPECT_NE(y.find("translation y -8.2 N reached the compliance limit -8 N"), std::string::npos) << y;
    EXPECT_NE(simulation::findAxisAtLimit(SimTK::Vec6(0, -1.5, 0, 0, 0, 0), limits).find("rotation y"), std::string::npos);
}

// Closed form: a force side beyond onset x the constraint's limit on that side is replaced by it
// and flagged; sides inside it, moment sides (about another point) and locked axes are kept.
TEST(GraspSwitchRelease, CapAtSlipOnsetCapsOnlyForceSidesBeyondTheConstraintsOnset) {
    simulation::ComplianceReleaseLimits limits;
    limits.lower = SimTK::Vec6(0.9, 0.1, 0.1, 15, 8, 7);
    limits.upper = SimTK::Vec6(0.1, 0.1, 0.1, 6, 11, 20);
    const SimTK::Vec6 box(0.5, 0.5, 0.5, 13.7, 13.7, 13.7);
    std::array<bool, 6> locked{};
    locked[5] = true;
    simulation::capAtSlipOnset(limits, box, box, locked, 0.99);
    EXPECT_DOUBLE_EQ(limits.lower[0], 0.9);  // a moment side, kept
    EXPECT_FALSE(limits.lowerAtSlipOnset[0]);
    EXPECT_DOUBLE_EQ(limits.lower[3], 0.99 * 13.7);
    EXPECT_TRUE(limits.lowerAtSlipOnset[3]);
    EXPECT_DOUBLE_EQ(limits.upper[3], 6);
    EXPECT_FALSE(limits.upperAtSlipOnset[3]);
    EXPECT_DOUBLE_EQ(limits.upper[4], 11);
    EXPECT_DOUBLE_EQ(limits.upper[5], 20);  // locked: the constraint holds any load there
    EXPECT_FALSE(limits.upperAtSlipOnset[5]);
    const std::string reason = simulation::findAxisAtLimit(SimTK::Vec6(0, 0, 0, -13.6, 0, 0), limits);
    EXPECT_NE(reason.find("translation x -13.6 N reached the constraint's slip onset"), std::string::npos) << reason;
    EXPECT_EQ(simulation::describeSlipOnsetSides(limits), " (translation x lower side at the constraint's slip onset)");
}

// The load's own direction (findDirectionAtLimit) on a hand-made stiff pinch (contacts at x = -d
// and +d, each pressing with N, friction mu): its per-axis sides along y and z are 2 mu N each,
// but the two cones bound the total tangential force, 2 mu N in any direction (Coulomb): a held
// load of 4.5 N along y and z together (6.36 N) is inside both sides and past the cones; 4 N of
// each (5.66 N) is inside both.
TEST(GraspSwitchRelease, FindDirectionAtLimitSharesTheCones) {
    const double mu = 0.6, N = 5;
    simulation::ComplianceReleaseLimits limits = makeStiffPinch(mu, N);
    limits.lower = SimTK::Vec6(1, 1, 1, 100, 2 * mu * N, 2 * mu * N);
    limits.upper = limits.lower;
    const SimTK::Vec6 past(0, 0, 0, 0, -4.5, -4.5), inside(0, 0, 0, 0, -4, -4);  // reactions: the load's opposite
    EXPECT_TRUE(simulation::findAxisAtLimit(past, limits).empty());
    const std::string text = simulation::findComplianceLimitReached(past, limits);
    EXPECT_NE(text.find("reached the compliance model's onset along it"), std::string::npos) << text;
    EXPECT_TRUE(simulation::findComplianceLimitReached(inside, limits).empty());
    // A side is reported first; without the contacts only the sides count.
    EXPECT_NE(simulation::findComplianceLimitReached(SimTK::Vec6(0, 0, 0, 0, -6.1, 0), limits).find("translation y"),
              std::string::npos);
    limits.contacts_O.clear();
    EXPECT_TRUE(simulation::findComplianceLimitReached(past, limits).empty());
}

// The release witness's value on the same pinch: the two cones give way together at a total
// tangential load of 2 mu N in any direction (the slip up to there, microns, is far below the
// model's 2 mm), so the direction margin is 2 mu N - |load| from half of that load on, |load|
// below it; the witness is the smaller of it and the per-axis margin.
TEST(GraspSwitchRelease, DirectionMarginIsTheDistanceToTheConesAlongTheLoad) {
    const double mu = 0.6, N = 5, ultimate = 2 * mu * N;
    simulation::ComplianceReleaseLimits limits = makeStiffPinch(mu, N);
    limits.lower = SimTK::Vec6(10, 10, 10, 100, ultimate, ultimate);
    limits.upper = limits.lower;
    for (double a : {2.5, 4.0, 4.5, 5.0}) {  // held along y and z at once: |load| = a sqrt(2)
        const SimTK::Vec6 reaction(0, 0, 0, 0, -a, -a);
        const double norm = a * std::sqrt(2.0);
        EXPECT_NEAR(simulation::findDirectionMargin(reaction, limits), std::min(ultimate - norm, norm), 1e-6 * ultimate) << a;
        EXPECT_EQ(simulation::findLimitMargin(reaction, limits) <= 0, !simulation::findComplianceLimitReached(reaction, limits).empty()) << a;
    }
    EXPECT_NEAR(simulation::findLimitMargin(SimTK::Vec6(0, 0, 0, 0, -1, 0), limits), 1.0, 1e-6);  // the direction (its margin |load|), not the y side (5)
    EXPECT_NEAR(simulation::findLimitMargin(SimTK::Vec6(0, 0, 0, 0, -5.5, 0), limits), ultimate - 5.5, 1e-6);  // the y side
    limits.contacts_O.clear();
    EXPECT_EQ(simulation::findDirectionMargin(SimTK::Vec6(0, 0, 0, 0, -4.5, -4.5), limits), SimTK::Infinity);
}

// The release give (ApproxOptions::releaseGive) is the model's onset: on a pinch with soft fingers
// (compliance c_f = 0.1 mm/N, in series with the pads' k_t) a tangential load F along y moves the
// object by F / K_y, K_y = 2 / (c_f + 1 / k_t), long before the cones (2 mu N = 30 N). So the
// direction margin is d K_y - F for a give d, whichever d: closed form at three gives, none of
// them the default.
TEST(GraspSwitchRelease, ReleaseGiveIsTheModelsOnsetAlongTheLoad) {
    const double mu = 0.5, N = 30, fingerCompliance = 1e-4, kt = 4e5;
    const double K_y = 2 / (fingerCompliance + 1 / kt);  // N/m, about 19.5 N per mm
    simulation::ComplianceReleaseLimits limits = makeStiffPinch(mu, N);
    for (grasp::CompliantContact& c : limits.contacts_O) c.fingerCompliance_G = fingerCompliance * Eigen::Matrix3d::Identity();
    for (double give : {0.4e-3, 0.7e-3, 1.3e-3}) {
        limits.slipDistance = give;
        const double onset = give * K_y;
        ASSERT_LT(onset, 2 * mu * N);
        for (double fraction : {0.6, 0.9}) {
            const SimTK::Vec6 reaction(0, 0, 0, 0, -fraction * onset, 0);
            EXPECT_NEAR(simulation::findDirectionMargin(reaction, limits), onset - fraction * onset, 1e-6 * onset) << give;
            EXPECT_TRUE(simulation::findDirectionAtLimit(reaction, limits).empty()) << give;
        }
        EXPECT_FALSE(simulation::findDirectionAtLimit(SimTK::Vec6(0, 0, 0, 0, -1.01 * onset, 0), limits).empty()) << give;
    }
}
