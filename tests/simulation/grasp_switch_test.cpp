// The grasp approximation (--mode approx, thesis Figure 4.1) checked against the full-contact run
// of the same scenario as the second method: once the switch engages, the object held by the
// friction-limited bushing must stay where full contact keeps it.

#include "graspsim/simulation/grasp_simulation.h"

#include "graspsim/simulation/grasp_experiment.h"
#include "graspsim/simulation/grasp_scene.h"
#include "graspsim/simulation/grasp_switch.h"

#include "graspsim/error.h"
#include "graspsim/grasp/limited_bushing.h"
#include "graspsim/grasp/limited_weld.h"
#include "graspsim/scenario/scenario_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace graspsim;

namespace {

simulation::SimulationOptions makeOptions(simulation::SimulationMode mode, double duration,
                                          simulation::ApproxConstraint constraint = simulation::ApproxConstraint::Bushing) {
    simulation::SimulationOptions options;
    options.mode = mode;
    options.duration = duration;
    options.approx.constraint = constraint;
    return options;
}

// Largest position (m) and orientation (rad) difference between two runs of the same scenario at
// the common output times from `from` on (both runs sample at the same times).
struct Deviation {
    double distance = 0;
    double angle = 0;
};
Deviation findLargestDeviation(const simulation::SimulationResult& a, const simulation::SimulationResult& b, double from) {
    Deviation worst;
    EXPECT_EQ(a.trajectory.size(), b.trajectory.size());
    for (std::size_t k = 0; k < std::min(a.trajectory.size(), b.trajectory.size()); ++k) {
        const simulation::TrajectorySample& x = a.trajectory[k];
        const simulation::TrajectorySample& y = b.trajectory[k];
        EXPECT_DOUBLE_EQ(x.time, y.time);
        if (x.time < from) continue;
        worst.distance = std::max(worst.distance, (x.p_GO - y.p_GO).norm());
        const double cosHalf = std::min(1.0, std::abs(~x.q_GO.asVec4() * y.q_GO.asVec4()));
        worst.angle = std::max(worst.angle, 2 * std::acos(cosHalf));
    }
    return worst;
}

// Q while engaged (the constraint's wrench spread over the tracked contacts) against the second
// method, the contact Q at the switch: at engagement both describe the same forces, so the first
// engaged sample is within 10 % of it; with nothing pulling, it never falls to Q_M.
void expectEngagedQualityContinuesTheContactQuality(const simulation::SimulationResult& r) {
    const auto first = std::find_if(r.trajectory.begin(), r.trajectory.end(), [&](const simulation::TrajectorySample& t) {
        return t.time > r.summary.engageTime + 1e-12;
    });
    ASSERT_NE(first, r.trajectory.end());
    EXPECT_NEAR(first->graspQuality, r.summary.qAtEngage, 0.1 * r.summary.qAtEngage);
    EXPECT_GT(r.summary.minEngagedGraspQuality, r.summary.qMinimum);
}

// The tracked fingertips do not sink further into the object while engaged (not visibly: <= 0.1 mm,
// ApproxOptions::maxEngagedPenetration) under gravity alone. Bounded for the rigid weld; for the
// compliant bushing by its stiffness at engagement, chosen from the friction limits so that its
// elastic displacement at them stays within the bound (grasp_switch.cpp, calcEngagedStiffness),
// and, where it turns by the default's compliance model, by the locked fingers following the turn
// (finger_follow.h).
void expectNoPenetrationGrowth(const simulation::SimulationResult& r) {
    EXPECT_GT(r.summary.engagedPenetrationAtEngage, 0);  // the skin compression the grasp engages with
    EXPECT_LE(r.summary.maxEngagedPenetrationGrowth, simulation::ApproxOptions().maxEngagedPenetration);
}

// Both realizations against the full-contact run of `scenario` (the second method): engaged once,
// after the grasp settled, and within 2 mm and 2 degrees of the full-contact object for 2 s.
void expectBothRealizationsFollowFullContact(const std::string& scenario) {
    const scenario::Scenario s = scenario::findBuiltinScenario(scenario);
    const double duration = s.simulation.settleTime + 2.0;
    const auto full = simulation::runGraspSimulation(s, makeOptions(simulation::SimulationMode::Full, duration));
    ASSERT_TRUE(full.summary.complete) << full.summary.failure;
    for (const auto constraint : {simulation::ApproxConstraint::Bushing, simulation::ApproxConstraint::Weld}) {
        SCOPED_TRACE(simulation::toString(constraint));
        const auto approx = simulation::runGraspSimulation(s, makeOptions(simulation::SimulationMode::Approx, duration, constraint));
        ASSERT_TRUE(approx.summary.complete) << approx.summary.failure;
        ASSERT_TRUE(approx.summary.engaged);
        ASSERT_EQ(approx.events.size(), 1u) << approx.events.back().reason;
        EXPECT_GE(approx.summary.engageTime, s.simulation.settleTime - 1e-9);
        EXPECT_LE(approx.summary.engageTime, duration - 2.0 + 1e-9);
        EXPECT_TRUE(approx.summary.held);
        const Deviation d = findLargestDeviation(approx, full, approx.summary.engageTime);
        EXPECT_LT(d.distance, 0.002) << "object " << d.distance << " m from the full-contact object";
        EXPECT_LT(d.angle, 2 * SimTK::Pi / 180) << "object turned " << d.angle << " rad from the full-contact object";
        expectEngagedQualityContinuesTheContactQuality(approx);
        expectNoPenetrationGrowth(approx);
    }
}

// Largest distance of the object, at any sample from `from` on, from the point `p_G` (m).
double findLargestDistanceFrom(const simulation::SimulationResult& r, double from, const SimTK::Vec3& p_G) {
    double worst = 0;
    for (const simulation::TrajectorySample& t : r.trajectory) {
        if (t.time >= from) worst = std::max(worst, (t.p_GO - p_G).norm());
    }
    return worst;
}

}  // namespace

// Oracle: the full-contact run. Gravity sags the bushing by at most g / w^2 = 0.25 mm (the default
// stiffness; engagement only stiffens it), well inside 2 mm.
TEST(GraspSwitch, BallClutchEngagesAfterSettlingAndHoldsTheObjectWhereFullContactDoes) {
    const scenario::Scenario s = scenario::findBuiltinScenario("ball-clutch");
    const double duration = s.simulation.settleTime + 1.0;
    const auto approx = simulation::runGraspSimulation(s, makeOptions(simulation::SimulationMode::Approx, duration));
    const auto full = simulation::runGraspSimulation(s, makeOptions(simulation::SimulationMode::Full, duration));
    ASSERT_TRUE(approx.summary.complete) << approx.summary.failure;
    ASSERT_TRUE(full.summary.complete) << full.summary.failure;
    ASSERT_TRUE(approx.summary.engaged);
    ASSERT_EQ(approx.events.size(), 1u) << approx.events.back().reason;
    EXPECT_EQ(approx.events[0].kind, simulation::GraspEventKind::Engage);
    EXPECT_GT(approx.summary.engageTime, s.controller.approachTime);
    EXPECT_LT(approx.summary.releaseTime, 0);
    EXPECT_GE(approx.summary.qAtEngage, approx.summary.qThreshold);
    EXPECT_GT(approx.summary.qThreshold, 0);
    EXPECT_TRUE(approx.summary.held);
    EXPECT_EQ(approx.summary.engageObstacleAtEnd, "");  // engaged at the end
    const double gap = findLargestDistanceFrom(approx, approx.summary.engageTime, full.trajectory.back().p_GO);
    EXPECT_LT(gap, 0.002) << "approx object strays " << gap << " m from the full-contact final position";
}

TEST(GraspSwitch, BallClutchBushingAndWeldFollowFullContactForTwoSeconds) {
    expectBothRealizationsFollowFullContact("ball-clutch");
}

TEST(GraspSwitch, PhonePinchBushingAndWeldFollowFullContactForTwoSeconds) {
    expectBothRealizationsFollowFullContact("phone-pinch");
}

// The merged weld's object hangs from the palm (grasp_scene.h). Until its release a Ground weld
// holds it where the full-contact run's Ground lock does (second method: that run's samples), to
// the integrator's constraint error (CPodes keeps a position constraint only to its tolerance; it
// drifts about 1e-5 m/s here, 5 um by the release at 0.5 s); once
// engaged with every axis stuck, the weld holds it by the palm-object mobilizer lock, so it moves
// exactly with the palm (its pose in the palm frame stays as engaged, to round-off).
TEST(GraspSwitch, WeldObjectIsHeldByTheGroundWeldThenByTheMobilizerLock) {
    const scenario::Scenario s = scenario::findBuiltinScenario("ball-clutch");
    const double duration = s.simulation.settleTime + 0.5;
    const auto full = simulation::runGraspSimulation(s, makeOptions(simulation::SimulationMode::Full, duration));
    ASSERT_TRUE(full.summary.complete) << full.summary.failure;
    std::vector<double> heldTimes;
    std::vector<SimTK::Vec3> heldPositions;
    int engagedSamples = 0, lockedSamples = 0;
    bool haveEngagedPose = false;
    SimTK::Transform X_PO_engaged;
    double drift = 0;
    const simulation::SampleObserver observe = [&](const simulation::GraspExperiment& experiment, const SimTK::State& state) {
        const simulation::GraspScene& scene = experiment.getScene();
        const simulation::GraspSwitch* grasp = experiment.findSwitch();
        EXPECT_EQ(scene.getObject().getParentMobilizedBody().getMobilizedBodyIndex(), scene.getPalm().getMobilizedBodyIndex());
        if (scene.isObjectHeld(state)) {
            heldTimes.push_back(state.getTime());
            heldPositions.push_back(scene.getObject().getBodyOriginLocation(state));
        }
        ASSERT_NE(grasp, nullptr);
        if (!grasp->isEngaged(state)) return;
        ++engagedSamples;
        const auto* weld = dynamic_cast<const grasp::LimitedWeld*>(&experiment.getApproximation()->getAttachment());
        ASSERT_NE(weld, nullptr);
        if (weld->isHeldByLock(state)) ++lockedSamples;
        const SimTK::Transform X_PO = ~scene.getPalm().getBodyTransform(state) * scene.getObject().getBodyTransform(state);
        if (!haveEngagedPose) {
            X_PO_engaged = X_PO;
            haveEngagedPose = true;
        }
        drift = std::max(drift, (X_PO.p() - X_PO_engaged.p()).norm());
    };
    const auto weld = simulation::runGraspSimulation(
        s, makeOptions(simulation::SimulationMode::Approx, duration, simulation::ApproxConstraint::Weld), {}, observe);
    ASSERT_TRUE(weld.summary.complete) << weld.summary.failure;
    ASSERT_TRUE(weld.summary.engaged);
    ASSERT_FALSE(heldTimes.empty());
    for (std::size_t k = 0; k < heldTimes.size(); ++k) {
        const auto same = std::find_if(full.trajectory.begin(), full.trajectory.end(),
                                       [&](const simulation::TrajectorySample& t) { return t.time == heldTimes[k]; });
        ASSERT_NE(same, full.trajectory.end());
        EXPECT_LT((heldPositions[k] - same->p_GO).norm(), 1e-5) << "at t = " << heldTimes[k];
    }
    EXPECT_GT(engagedSamples, 40);
    EXPECT_EQ(lockedSamples, engagedSamples);
    EXPECT_LT(drift, 1e-12);
}

// The switch keeps its record in the State: each recorded sample carries the events up to its
// own time (none up to the engagement, the engage event after it), the automatic Q_Th appears
// once set, and a State copied before the engagement keeps its empty history after the run went on.
// Oracle: the run's own event list (summary) and the sample times.
TEST(GraspSwitch, EachStateCarriesItsOwnRecord) {
    const scenario::Scenario s = scenario::findBuiltinScenario("phone-pinch");
    std::vector<SimTK::State> samples;
    const simulation::SampleObserver observe = [&](const simulation::GraspExperiment&, const SimTK::State& state) {
        samples.push_back(state);
    };
    const auto r = simulation::runGraspSimulation(
        s, makeOptions(simulation::SimulationMode::Approx, s.simulation.settleTime + 0.3), {}, observe);
    ASSERT_TRUE(r.summary.complete) << r.summary.failure;
    ASSERT_TRUE(r.summary.engaged);
    ASSERT_FALSE(r.events.empty());
    const double engageTime = r.events.front().time;
    // A fresh scene reads the copied States (the record lives in them, not in the switch).
    simulation::SimulationOptions options = makeOptions(simulation::SimulationMode::Approx, 1);
    const simulation::GraspExperiment experiment(s, options);
    const simulation::GraspSwitch& grasp = *experiment.findSwitch();
    int before = 0, after = 0;
    for (const SimTK::State& state : samples) {
        const std::vector<simulation::GraspEvent>& events = grasp.getEvents(state);
        if (state.getTime() <= engageTime) {  // a sample at an event's instant precedes the event
            EXPECT_TRUE(events.empty()) << "t = " << state.getTime();
            ++before;
        } else {
            ASSERT_FALSE(events.empty()) << "t = " << state.getTime();
            EXPECT_EQ(events.front().time, engageTime);
            EXPECT_EQ(grasp.getQualityThreshold(state), r.summary.qThreshold);
            ++after;
        }
    }
    EXPECT_GT(before, 10);
    EXPECT_GT(after, 10);
}

TEST(GraspSwitch, PhonePinchEngages) {
    const scenario::Scenario s = scenario::findBuiltinScenario("phone-pinch");
    const auto r = simulation::runGraspSimulation(s, makeOptions(simulation::SimulationMode::Approx, s.simulation.settleTime + 0.3));
    ASSERT_TRUE(r.summary.complete) << r.summary.failure;
    ASSERT_TRUE(r.summary.engaged);
    EXPECT_GT(r.summary.engageTime, s.controller.approachTime);
    EXPECT_GE(r.summary.qAtEngage, r.summary.qThreshold);
    EXPECT_TRUE(r.summary.held);
}

// Engagement waits for every contact to stick: slower than the scenario's transition velocity. At
// 0.3 mm/s, under the ball's own 0.36-0.41 mm/s creep of the index finger's middle phalanx after
// the settle, the switch never engages, and the run says which of its tests failed. The oracle is
// the test itself: the speed named is at or above the transition velocity named. A run that ends
// before the settle time names that instead.
TEST(GraspSwitch, ARunThatNeverEngagesSaysWhichTestFailed) {
    scenario::Scenario s = scenario::findBuiltinScenario("ball-clutch");
    s.contact.transitionVelocity = 3e-4;
    const auto r = simulation::runGraspSimulation(s, makeOptions(simulation::SimulationMode::Approx, s.simulation.settleTime + 0.1));
    ASSERT_TRUE(r.summary.complete) << r.summary.failure;
    EXPECT_FALSE(r.summary.engaged);
    const std::string& text = r.summary.engageObstacleAtEnd;
    const std::size_t at = text.find(" slips at ");
    ASSERT_NE(at, std::string::npos) << text;
    EXPECT_EQ(text.rfind("the contact of ", 0), 0u) << text;
    EXPECT_NE(text.find("not below the transition velocity 0.0003 m/s"), std::string::npos) << text;
    EXPECT_GE(std::stod(text.substr(at + 10)), 3e-4) << text;

    const auto early = simulation::runGraspSimulation(s, makeOptions(simulation::SimulationMode::Approx, 0.8 * s.simulation.settleTime));
    ASSERT_TRUE(early.summary.complete) << early.summary.failure;
    EXPECT_EQ(early.summary.engageObstacleAtEnd, "before the settle time, 1 s");
}

// A slide allowance below the gravity sag releases at the first check after engagement: the
// contacts come back, the fingers unlock, and the switch re-engages once Q is back above Q_Th.
TEST(GraspSwitch, ReleasesWhenTheObjectSlidesAndReengages) {
    const scenario::Scenario s = scenario::findBuiltinScenario("phone-pinch");
    simulation::SimulationOptions options = makeOptions(simulation::SimulationMode::Approx, s.simulation.settleTime + 0.1);
    options.approx.releaseSlideDistance = 1e-6;
    const auto r = simulation::runGraspSimulation(s, options);
    ASSERT_TRUE(r.summary.complete) << r.summary.failure;
    ASSERT_GE(r.events.size(), 2u);
    EXPECT_EQ(r.events[1].kind, simulation::GraspEventKind::Release);
    EXPECT_NE(r.events[1].reason.find("slid"), std::string::npos) << r.events[1].reason;
    EXPECT_GT(r.summary.releaseTime, r.summary.engageTime);
    for (std::size_t k = 0; k < r.events.size(); ++k) EXPECT_EQ(r.events[k].kind, k % 2 ? simulation::GraspEventKind::Release : simulation::GraspEventKind::Engage);
    EXPECT_TRUE(r.summary.held);
}

TEST(GraspSwitch, RejectsBadThresholdsBeforeSimulating) {
    const scenario::Scenario s = scenario::findBuiltinScenario("phone-pinch");
    simulation::SimulationOptions options = makeOptions(simulation::SimulationMode::Approx, 0.1);
    options.approx.qThreshold = 1.0;
    options.approx.qMinimum = 2.0;
    EXPECT_THROW(simulation::runGraspSimulation(s, options), InputError);
    options.approx.qMinimum = 0;
    options.approx.releaseSlideDistance = 0;
    EXPECT_THROW(simulation::runGraspSimulation(s, options), InputError);
}

// Under every perturbation of both experiments the approximation's hold/slide verdict is full
// contact's (the second method), for both realizations, at the end of the perturbation; where full
// contact holds, the approximated object stays within 2 mm of it.
class PerturbationVerdict : public ::testing::TestWithParam<std::pair<const char*, const char*>> {};

TEST_P(PerturbationVerdict, MatchesFullContact) {
    const scenario::Scenario s = scenario::findBuiltinScenario(GetParam().first);
    const scenario::Perturbation* p = s.findPerturbation(GetParam().second);
    ASSERT_NE(p, nullptr);
    simulation::SimulationOptions options = makeOptions(simulation::SimulationMode::Full, p->start + p->duration);
    options.perturbation = p->name;
    const auto full = simulation::runGraspSimulation(s, options);
    ASSERT_TRUE(full.summary.complete) << full.summary.failure;
    for (const auto constraint : {simulation::ApproxConstraint::Bushing, simulation::ApproxConstraint::Weld}) {
        SCOPED_TRACE(simulation::toString(constraint));
        options.mode = simulation::SimulationMode::Approx;
        options.approx.constraint = constraint;
        const auto approx = simulation::runGraspSimulation(s, options);
        ASSERT_TRUE(approx.summary.complete) << approx.summary.failure;
        EXPECT_TRUE(approx.summary.engaged);
        EXPECT_EQ(approx.summary.held, full.summary.held);
        // Below capacity (full contact holds), the approximated object follows the full-contact
        // object within 2 mm through the load (issue "holding capacity"; measured with the bushing:
        // ball f1 1.23 mm, ball f2 0.43 mm, phone f2 1.45 mm).
        if (full.summary.held) EXPECT_LT(findLargestDeviation(approx, full, 0).distance, 0.002);
    }
}

INSTANTIATE_TEST_SUITE_P(BothExperiments, PerturbationVerdict,
                         ::testing::Values(std::make_pair("ball-clutch", "f1"), std::make_pair("ball-clutch", "f2"),
                                           std::make_pair("phone-pinch", "f1"), std::make_pair("phone-pinch", "f2")));

// An overload release must hand back an object that full contact holds at that load (issue
// "holding capacity"). The phone pulled down by 0.9 N from 1.5 s: full contact holds it (the
// second method, the oracle), letting it pivot with the fingers; the engaged constraint reaches its
// rotation limit first and slides, driving the phone into a locked fingertip. Released only after
// the 5 mm slide, the deepened pad threw the phone out (lost with both constraints); released once
// a pad has sunk releasePenetration deeper, full contact catches it.
TEST(GraspSwitch, OverloadReleaseHandsBackAnObjectFullContactHolds) {
    scenario::Scenario s = scenario::findBuiltinScenario("phone-pinch");
    scenario::Perturbation pull;
    pull.name = "pull";
    pull.force = {0, -0.9, 0};
    pull.start = 1.5;
    pull.duration = 1.0;
    s.perturbations.push_back(pull);
    simulation::SimulationOptions options = makeOptions(simulation::SimulationMode::Full, pull.start + pull.duration);
    options.perturbation = pull.name;
    const auto full = simulation::runGraspSimulation(s, options);
    ASSERT_TRUE(full.summary.complete) << full.summary.failure;
    ASSERT_TRUE(full.summary.held) << "the oracle: full contact holds the phone under the pull";
    for (const auto constraint : {simulation::ApproxConstraint::Bushing, simulation::ApproxConstraint::Weld}) {
        SCOPED_TRACE(simulation::toString(constraint));
        options.mode = simulation::SimulationMode::Approx;
        options.approx.constraint = constraint;
        const auto approx = simulation::runGraspSimulation(s, options);
        ASSERT_TRUE(approx.summary.complete) << approx.summary.failure;
        const auto overload = std::find_if(approx.events.begin(), approx.events.end(), [&](const simulation::GraspEvent& e) {
            return e.kind == simulation::GraspEventKind::Release && e.time >= pull.start;
        });
        ASSERT_NE(overload, approx.events.end()) << "the pull overloads the engaged constraint";
        EXPECT_TRUE(approx.summary.held) << "released at " << overload->time << " s: " << overload->reason;
        // Once full contact has the pivoted phone steady, the switch engages again and stays: with
        // the tracked normals taken again from the box at palm-fixed points it engaged and
        // released every 20 ms (about 70 switches in the second after the pull).
        EXPECT_LE(approx.events.size(), 6u);
        EXPECT_LT(approx.summary.maxEngagedPenetrationGrowth, 2 * simulation::ApproxOptions{}.releasePenetration);
    }
}

// Phone f1 overloads the pinch (2 N, mostly along the pinch axis, unloads one finger: the engaged
// Q falls below Q_M, after the default's compliance trigger has fired). The release hands back to contact with the object's velocity unchanged:
// the jump measured across the switch (before it, and in the state the integrator restarts
// from) stays below 1e-3 m/s; the fingertips never sink more than the bound into the phone.
TEST(GraspSwitch, OverloadReleaseHandsBackToContactWithoutAVelocityJump) {
    const scenario::Scenario s = scenario::findBuiltinScenario("phone-pinch");
    const scenario::Perturbation* p = s.findPerturbation("f1");
    ASSERT_NE(p, nullptr);
    for (const auto constraint : {simulation::ApproxConstraint::Bushing, simulation::ApproxConstraint::Weld}) {
        SCOPED_TRACE(simulation::toString(constraint));
        simulation::SimulationOptions options = makeOptions(simulation::SimulationMode::Approx, p->start + 0.1, constraint);
        options.perturbation = "f1";
        const auto r = simulation::runGraspSimulation(s, options);
        ASSERT_TRUE(r.summary.complete) << r.summary.failure;
        ASSERT_GE(r.events.size(), 2u);
        EXPECT_EQ(r.events[1].kind, simulation::GraspEventKind::Release);
        EXPECT_GE(r.events[1].time, p->start - 1e-9);
        // The default bushing's compliance trigger sees the overload first (torque y; 1.5003 s); the
        // weld, on the thesis's switch, at the quality check.
        const char* rule = constraint == simulation::ApproxConstraint::Bushing ? "reached the compliance limit" : "Q < Q_M";
        EXPECT_NE(r.events[1].reason.find(rule), std::string::npos) << r.events[1].reason;
        for (const simulation::GraspEvent& e : r.events) EXPECT_LT(e.velocityJump, 1e-3) << simulation::toString(e.kind) << " at " << e.time;
        // The phone slips out of the pinch after the release: sliding contacts are no firm grasp,
        // so the switch must not re-engage (it used to, 10 ms later, and drag the sliding phone
        // 0.77 mm into the locked fingertips).
        EXPECT_EQ(r.events.size(), 2u);
        expectNoPenetrationGrowth(r);
    }
}

// --limits compliance: two-sided limits from the grasp's compliance model at engagement. Oracles:
// the full-contact run (the object stays within 2 mm of it, as with the thesis's box), and the
// weight: at rest the bushing carries m g upward (to 5 %) inside both sides of every axis (no axis
// slides), which fails if a side carried the engagement's wrench W0 with the wrong sign.
TEST(GraspSwitch, BallClutchComplianceLimitsAreTwoSidedAndHoldTheWeight) {
    const scenario::Scenario s = scenario::findBuiltinScenario("ball-clutch");
    const double duration = s.simulation.settleTime + 0.5;
    simulation::SimulationOptions options = makeOptions(simulation::SimulationMode::Approx, duration);
    options.approx.limitModel = grasp::FrictionLimitModel::Compliance;
    SimTK::Vec6 lower(0), upper(0), force(0);
    SimTK::Rotation R_GA;
    bool sliding = false;
    const simulation::SampleObserver observe = [&](const simulation::GraspExperiment& experiment, const SimTK::State& state) {
        const auto* bushing = dynamic_cast<const grasp::LimitedBushing*>(&experiment.getApproximation()->getAttachment());
        ASSERT_NE(bushing, nullptr);
        if (!bushing->isEngaged(state)) return;
        experiment.getScene().getSystem().realize(state, SimTK::Stage::Velocity);
        lower = bushing->findEffectiveLowerLimits(state);
        upper = bushing->findEffectiveLimits(state);
        force = bushing->findGeneralizedForce(state);
        // The anchor frame A, in which the generalized force is expressed: R_GH R_HF R_FA.
        R_GA = experiment.getScene().getPalm().getBodyRotation(state) * bushing->getFrameOnH(state).R() *
               bushing->findAnchorTransform(state).R();
        sliding = false;
        for (int k = 0; k < 6; ++k) sliding = sliding || bushing->isSliding(state, static_cast<grasp::BushingAxis>(k));
    };
    const auto approx = simulation::runGraspSimulation(s, options, {}, observe);
    const auto full = simulation::runGraspSimulation(s, makeOptions(simulation::SimulationMode::Full, duration));
    ASSERT_TRUE(approx.summary.complete) << approx.summary.failure;
    ASSERT_TRUE(approx.summary.engaged);
    ASSERT_EQ(approx.events.size(), 1u) << approx.events.back().reason;
    EXPECT_NE(approx.events[0].reason.find("compliance limits"), std::string::npos) << approx.events[0].reason;
    double asymmetry = 0;
    for (int k = 0; k < 6; ++k) {
        EXPECT_GT(lower[k], 0) << k;
        EXPECT_GT(upper[k], 0) << k;
        asymmetry = std::max(asymmetry, std::abs(upper[k] - lower[k]) / std::max(upper[k], lower[k]));
    }
    EXPECT_GT(asymmetry, 0.2) << "lower " << lower << " upper " << upper;
    const double weight = s.object.mass * std::abs(s.world.gravity[1]);
    const SimTK::Vec3 F_G = R_GA * force.getSubVec<3>(3);
    EXPECT_NEAR(F_G[1], weight, 0.05 * weight) << F_G;
    EXPECT_FALSE(sliding);
    for (int k = 0; k < 6; ++k) {
        EXPECT_LT(force[k], upper[k]) << k;
        EXPECT_GT(force[k], -lower[k]) << k;
    }
    const double gap = findLargestDistanceFrom(approx, approx.summary.engageTime, full.trajectory.back().p_GO);
    EXPECT_LT(gap, 0.002) << "approx object strays " << gap << " m from the full-contact final position";
    // The result's constraint samples (constraint.csv) report both sides as the bushing holds them.
    ASSERT_FALSE(approx.constraint.empty());
    for (int k = 0; k < 6; ++k) {
        EXPECT_EQ(approx.constraint.back().limits[k], upper[k]) << k;
        EXPECT_EQ(approx.constraint.back().lowerLimits[k], lower[k]) << k;
    }
}
