// The `multi` attachment of the grasp approximation (--attach multi) checked against the
// full-contact run of the same scenario as the second method: engaged after settling, the object
// within 2 mm and 2 degrees of the full-contact object for 2 s; under a push that makes one finger
// lose its spot, that finger is detached and stops following while the others hold, as full
// contact holds.

#include "graspsim/simulation/grasp_simulation.h"

#include "graspsim/error.h"
#include "graspsim/grasp/multi_attachment.h"
#include "graspsim/scenario/scenario_file.h"
#include "graspsim/simulation/grasp_experiment.h"
#include "graspsim/simulation/grasp_scene.h"
#include "graspsim/simulation/multi_attachment_switch.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

using namespace graspsim;

namespace {

simulation::SimulationOptions makeOptions(simulation::SimulationMode mode, double duration, const std::string& perturbation = "none") {
    simulation::SimulationOptions options;
    options.mode = mode;
    options.duration = duration;
    options.perturbation = perturbation;
    options.approx.attach = simulation::ApproxAttach::Multi;
    return options;
}

// Largest object position (m) and orientation (rad) difference between two runs from `from` on.
std::pair<double, double> findLargestDeviation(const simulation::SimulationResult& a, const simulation::SimulationResult& b,
                                               double from) {
    double distance = 0, angle = 0;
    EXPECT_EQ(a.trajectory.size(), b.trajectory.size());
    for (std::size_t k = 0; k < std::min(a.trajectory.size(), b.trajectory.size()); ++k) {
        const simulation::TrajectorySample& x = a.trajectory[k];
        const simulation::TrajectorySample& y = b.trajectory[k];
        if (x.time < from) continue;
        distance = std::max(distance, (x.p_GO - y.p_GO).norm());
        angle = std::max(angle, 2 * std::acos(std::min(1.0, std::abs(~x.q_GO.asVec4() * y.q_GO.asVec4()))));
    }
    return {distance, angle};
}

void expectMultiFollowsFullContact(const std::string& name) {
    const scenario::Scenario s = scenario::findBuiltinScenario(name);
    const double duration = s.simulation.settleTime + 2.0;
    const auto full = simulation::runGraspSimulation(s, makeOptions(simulation::SimulationMode::Full, duration));
    const auto multi = simulation::runGraspSimulation(s, makeOptions(simulation::SimulationMode::Approx, duration));
    ASSERT_TRUE(full.summary.complete) << full.summary.failure;
    ASSERT_TRUE(multi.summary.complete) << multi.summary.failure;
    ASSERT_TRUE(multi.summary.engaged);
    ASSERT_EQ(multi.events.size(), 1u) << multi.events.back().reason;
    EXPECT_GE(multi.summary.engageTime, s.simulation.settleTime - 1e-9);
    EXPECT_LE(multi.summary.engageTime, duration - 2.0 + 1e-9);
    EXPECT_EQ(multi.summary.held, full.summary.held);
    // The attached fingertips' pairs are tracked while engaged (their skin depth at attachment
    // is > 0) and sink no deeper than the bound the parts are stiffened for.
    EXPECT_GT(multi.summary.engagedPenetrationAtEngage, 0);
    EXPECT_LE(multi.summary.maxEngagedPenetrationGrowth, simulation::ApproxOptions().maxEngagedPenetration);
    const auto [distance, angle] = findLargestDeviation(multi, full, multi.summary.engageTime);
    EXPECT_LT(distance, 0.002) << "object " << distance << " m from the full-contact object";
    EXPECT_LT(angle, 2 * SimTK::Pi / 180) << "object turned " << angle << " rad from the full-contact object";
}

}  // namespace

TEST(MultiAttachmentSwitch, BallClutchEngagesAfterSettlingAndFollowsFullContactForTwoSeconds) {
    expectMultiFollowsFullContact("ball-clutch");
}

// Two point contacts leave the phone free to turn about the pinch axis; the middle finger, which
// has no goal, keeps touching it (its pairs stay on) as in full contact.
TEST(MultiAttachmentSwitch, PhonePinchEngagesAfterSettlingAndFollowsFullContactForTwoSeconds) {
    expectMultiFollowsFullContact("phone-pinch");
}

// An 11 N push toward the little finger's side: full contact holds the ball; in multi the middle
// and index fingers stop pressing (10 ms apart) and are detached (with the parts stiffened from
// their loads, a 9 N push no longer unloads any finger): a detached finger's part carries nothing
// from then on and the finger is back in ordinary contact (its pairs on again, its PD still pressing
// it onto the ball), while the other parts hold the ball where full contact holds it. (That a detached
// finger no longer follows the object is shown with a closed form in multi_attachment_test.cpp.)
TEST(MultiAttachmentSwitch, ADetachedFingerCarriesNothingAndReturnsToContactWhileTheOthersHold) {
    scenario::Scenario s = scenario::findBuiltinScenario("ball-clutch");
    s.perturbations.push_back({"sideways", {0, 0, 11.0}, 1.5, 1.0});
    const double duration = 2.5;
    const auto full = simulation::runGraspSimulation(s, makeOptions(simulation::SimulationMode::Full, duration, "sideways"));
    ASSERT_TRUE(full.summary.complete) << full.summary.failure;
    ASSERT_TRUE(full.summary.held) << "the push must be one full contact holds";

    // Per sample: which parts are attached, the force of the detached ones, fingertip-goal distances.
    std::map<std::string, double> detachedForce, firstDetachedSample;
    std::map<std::string, int> contactSamples;  // samples after the detach with the finger in contact
    const auto observe = [&](const simulation::GraspExperiment& experiment, const SimTK::State& state) {
        const simulation::GraspScene& scene = experiment.getScene();
        const grasp::MultiAttachment& multi = *experiment.getApproximation()->getContext().multi;
        for (int i = 0; i < multi.getNumParts(); ++i) {
            const std::string& name = scene.getGoalEndEffectors()[static_cast<std::size_t>(i)];
            if (multi.isAttached(state, i) || state.getTime() < 1.0) continue;
            scene.getSystem().realize(state, SimTK::Stage::Velocity);
            detachedForce[name] = std::max(detachedForce[name], std::abs(multi.findPressingForce(state, i)));
            if (!firstDetachedSample.count(name)) firstDetachedSample[name] = state.getTime();
            const std::string body = scene.getModel().getDescription().findEndEffector(name)->body;
            for (const contact::ContactReport& c : scene.getCompliantContacts().findContactReports(state)) {
                if (c.bodyA == body && c.normalForce > 0) ++contactSamples[name];
            }
        }
    };
    const auto multi = simulation::runGraspSimulation(s, makeOptions(simulation::SimulationMode::Approx, duration, "sideways"),
                                                      {}, observe);
    ASSERT_TRUE(multi.summary.complete) << multi.summary.failure;
    ASSERT_GE(multi.events.size(), 2u);
    EXPECT_EQ(multi.events.front().kind, simulation::GraspEventKind::Engage);
    int detached = 0;
    for (const simulation::GraspEvent& e : multi.events) {
        EXPECT_NE(e.kind, simulation::GraspEventKind::Release) << e.reason;  // the others keep holding
        if (e.kind != simulation::GraspEventKind::Detach) continue;
        ++detached;
        const std::string name = e.reason.substr(0, e.reason.find(':'));
        SCOPED_TRACE(name);
        EXPECT_GE(e.time, 1.5 - 1e-9);  // only once pushed
        ASSERT_TRUE(firstDetachedSample.count(name));
        EXPECT_EQ(detachedForce[name], 0);  // carries nothing once detached
        EXPECT_GT(contactSamples[name], 0);
    }
    EXPECT_GE(detached, 1);
    EXPECT_LE(detached, 3);  // at least two fingers hold
    EXPECT_TRUE(multi.summary.held);
    const auto [distance, angle] = findLargestDeviation(multi, full, multi.summary.engageTime);
    EXPECT_LT(distance, 0.002) << "object " << distance << " m from the full-contact object";
    // Not bounded here: the orientation under this push, close to what full contact can hold, with
    // two of five fingers detached (3.4 degrees from full contact, measured 2026-11-22). The 2°
    // orientation bound (a visible tilt of the object in the hand) applies without perturbation
    // (the two tests above); under one, the verdict is what must agree.
    ::testing::Test::RecordProperty("orientation_deviation_deg", std::to_string(angle * 180 / SimTK::Pi));
}

// An overload release of `multi` must hand the object back to full contact without losing what
// full contact holds (issue "holding capacity"): the ball pulled down by 12 N, a load full contact
// holds (the oracle), and a sink bound (ApproxOptions::releasePenetration, 35 um here instead of
// 0.5 mm) that the index fingertip passes under it (it sinks about 0.04 mm in 20 ms). The whole
// approximation is released then and full contact keeps the ball. Detaching only the finger that
// sank was tried and lost the ball: the others' limits, frozen at engagement, then carried less
// than the pull, two more fingers left within 0.6 s and the last one could not hold it.
TEST(MultiAttachmentSwitch, AFingertipThatSinksReleasesToFullContactWhichKeepsTheBall) {
    scenario::Scenario s = scenario::findBuiltinScenario("ball-clutch");
    s.perturbations.push_back({"pull", {0, -12.0, 0}, 1.5, 1.0});
    const double duration = 2.5;
    const auto full = simulation::runGraspSimulation(s, makeOptions(simulation::SimulationMode::Full, duration, "pull"));
    ASSERT_TRUE(full.summary.complete) << full.summary.failure;
    ASSERT_TRUE(full.summary.held) << "the pull must be one full contact holds";
    simulation::SimulationOptions options = makeOptions(simulation::SimulationMode::Approx, duration, "pull");
    options.approx.releasePenetration = 3.5e-5;
    const auto multi = simulation::runGraspSimulation(s, options);
    ASSERT_TRUE(multi.summary.complete) << multi.summary.failure;
    const auto sank = std::find_if(multi.events.begin(), multi.events.end(), [](const simulation::GraspEvent& e) {
        return e.kind == simulation::GraspEventKind::Release && e.reason.find("sank") != std::string::npos;
    });
    ASSERT_NE(sank, multi.events.end()) << "a fingertip sinks past the bound under the pull";
    EXPECT_GE(sank->time, 1.5 - 1e-9);
    EXPECT_TRUE(multi.summary.held);
    const auto [distance, angle] = findLargestDeviation(multi, full, multi.summary.engageTime);
    EXPECT_LT(distance, 0.002) << "object " << distance << " m from the full-contact object";
}

// The "stopped pressing" detach is localized by a witness, not left to the next check: under the
// phone-pinch pull f1 the index finger unloads, and it is detached where its part's normal force
// crosses zero (oracle: the force at the detach is 0 to the localization tolerance; a 10-ms check
// found -0.58 N, with the fingertip 0.26 mm deeper in the phone by then). The 0.1-mm penetration
// bound (ApproxOptions::maxEngagedPenetration) then holds.
TEST(MultiAttachmentSwitch, DetachesAFingerWhereItsPressingForceCrossesZero) {
    const scenario::Scenario s = scenario::findBuiltinScenario("phone-pinch");
    const auto r = simulation::runGraspSimulation(s, makeOptions(simulation::SimulationMode::Approx, 1.6, "f1"));
    ASSERT_TRUE(r.summary.complete) << r.summary.failure;
    const auto detach = std::find_if(r.events.begin(), r.events.end(), [](const auto& e) { return e.kind == simulation::GraspEventKind::Detach; });
    ASSERT_NE(detach, r.events.end());
    const std::size_t at = detach->reason.find("normal force ");
    ASSERT_NE(at, std::string::npos) << detach->reason;
    const double force = std::stod(detach->reason.substr(at + 13));
    EXPECT_LE(force, 0.0);
    EXPECT_GT(force, -1e-3) << detach->reason;
    EXPECT_LE(r.summary.maxEngagedPenetrationGrowth, 1e-4);
}

TEST(MultiAttachmentSwitch, RejectsMultiWithTheWeldNamingAttach) {
    const scenario::Scenario s = scenario::findBuiltinScenario("phone-pinch");
    simulation::SimulationOptions options = makeOptions(simulation::SimulationMode::Approx, 0.1);
    options.approx.constraint = simulation::ApproxConstraint::Weld;
    try {
        simulation::checkApproxAttach(s, options);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("--attach"), std::string::npos) << e.what();
    }
    EXPECT_THROW(simulation::runGraspSimulation(s, options), InputError);
    options.approx.constraint = simulation::ApproxConstraint::Bushing;
    EXPECT_NO_THROW(simulation::checkApproxAttach(s, options));
}
