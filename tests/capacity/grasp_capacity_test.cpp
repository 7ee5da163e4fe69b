#include "graspsim/capacity/grasp_capacity.h"
#include "graspsim/capacity/overload.h"

#include "graspsim/contact/contact_parameters.h"
#include "graspsim/contact/friction_settings.h"
#include "graspsim/error.h"
#include "graspsim/scenario/scenario_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace graspsim::capacity {
namespace {

// The line through the pinch's two goals, in G, from the scenario's own goals and initial pose.
SimTK::Vec3 findPinchLine(const scenario::Scenario& s) {
    const model::Transform X_GO = s.object.findPose();
    const model::Vec3 a = X_GO.xformFrameVecToBase(s.goals.at("thumb_tip"));
    const model::Vec3 b = X_GO.xformFrameVecToBase(s.goals.at("index_tip"));
    return SimTK::Vec3(b[0] - a[0], b[1] - a[1], b[2] - a[2]).normalize();
}

GraspCapacityRequest makeTorque(const SimTK::Vec3& axis) {
    GraspCapacityRequest request;
    request.torque = true;
    request.direction = SimTK::UnitVec3(axis);
    request.directionName = "v";
    return request;
}

// Full contact against the default approximation (with `give`) along `request` on the ball (ramp at
// 6 N/s, then 1.25 x full contact's onset held `hold` s, as analysis/overload_times.py does): each
// release names every fragment in `reason`, and the approximation's ramp onset and held slip-onset
// time are full contact's within 10 %, the criterion.
void expectBallCellAgrees(const GraspCapacityRequest& request, const std::vector<std::string>& reason, double hold,
                          simulation::ApproxBushingGive give = simulation::ApproxBushingGive::Automatic) {
    const scenario::Scenario ball = scenario::findBuiltinScenario("ball-clutch");
    simulation::SimulationOptions options;
    options.integrator = simulation::IntegratorChoice::LinearlyImplicit;
    options.accuracy = 3e-4;
    options.approx.bushingGive = give;
    const GraspCapacity full = measureGraspCapacityRamp(ball, options, request);
    options.mode = simulation::SimulationMode::Approx;
    const GraspCapacity approx = measureGraspCapacityRamp(ball, options, request);
    ASSERT_TRUE(full.trace.figures.slipped);
    ASSERT_TRUE(approx.trace.figures.slipped);
    ASSERT_TRUE(approx.trace.figures.released);
    for (const std::string& part : reason) EXPECT_NE(approx.trace.releaseReason.find(part), std::string::npos) << approx.trace.releaseReason;
    EXPECT_NEAR(approx.trace.figures.slipOnsetLoad, full.trace.figures.slipOnsetLoad, 0.1 * full.trace.figures.slipOnsetLoad);
    const double load = 1.25 * full.trace.figures.slipOnsetLoad;
    options.mode = simulation::SimulationMode::Full;
    const GraspCapacity fullHeld = measureGraspCapacityConstant(ball, options, request, load, hold);
    options.mode = simulation::SimulationMode::Approx;
    const GraspCapacity approxHeld = measureGraspCapacityConstant(ball, options, request, load, hold);
    const OverloadFigures a = findOverloadFigures(approxHeld.trace.figures, approxHeld.start);
    const OverloadFigures f = findOverloadFigures(fullHeld.trace.figures, fullHeld.start);
    ASSERT_TRUE(f.slipped);
    ASSERT_TRUE(a.slipped);
    ASSERT_TRUE(a.released);
    EXPECT_LT(a.releaseTime, a.slipOnsetTime);
    EXPECT_NEAR(a.slipOnsetTime, f.slipOnsetTime, 0.1 * f.slipOnsetTime);
}

// The same ramp in full contact and with the approximation `given`, on the linearly implicit
// stepper at 3e-4: the second method and the one under test.
struct RampPair {
    GraspCapacity full;
    GraspCapacity approx;
};

simulation::SimulationOptions makeImplicitOptions(simulation::SimulationMode mode, const simulation::ApproxOptions& given) {
    simulation::SimulationOptions options;
    options.integrator = simulation::IntegratorChoice::LinearlyImplicit;
    options.accuracy = 3e-4;
    options.mode = mode;
    options.approx = given;
    return options;
}

// The approximation `given` alone, for a comparison with a full-contact ramp measured before.
GraspCapacity measureApproxRamp(const scenario::Scenario& s, const GraspCapacityRequest& request, const simulation::ApproxOptions& given) {
    return measureGraspCapacityRamp(s, makeImplicitOptions(simulation::SimulationMode::Approx, given), request);
}

RampPair measureFullAndApprox(const scenario::Scenario& s, const GraspCapacityRequest& request, const simulation::ApproxOptions& given) {
    RampPair ramps;
    ramps.full = measureGraspCapacityRamp(s, makeImplicitOptions(simulation::SimulationMode::Full, {}), request);
    ramps.approx = measureApproxRamp(s, request, given);
    return ramps;
}

// What a comparison of hand-backs needs: both slipped, and the approximation handed back.
::testing::AssertionResult bothSlipAfterAHandBack(const RampPair& ramps) {
    if (!ramps.full.trace.figures.slipped) return ::testing::AssertionFailure() << "full contact did not slip";
    if (!ramps.approx.trace.figures.slipped) return ::testing::AssertionFailure() << "the approximation did not slip";
    if (!ramps.approx.trace.figures.released) return ::testing::AssertionFailure() << "the approximation never handed back";
    return ::testing::AssertionSuccess();
}

GraspCapacityRequest makeBallRamp(const SimTK::Vec3& direction, const std::string& name) {
    GraspCapacityRequest request;
    request.direction = SimTK::UnitVec3(direction);
    request.directionName = name;
    request.rate = 6;
    request.maxRampDuration = 3.5;
    return request;
}

TEST(GraspCapacity, TorqueAboutThePinchLineIsRefusedAcrossItIsMeasured) {
    const scenario::Scenario pinch = scenario::findBuiltinScenario("phone-pinch");
    const SimTK::Vec3 line = findPinchLine(pinch);
    EXPECT_THROW(checkLoadResistible(pinch, makeTorque(line)), InputError);
    EXPECT_THROW(checkLoadResistible(pinch, makeTorque(-line)), InputError);
    // 4 deg off the line: still refused; 6 deg: measured.
    const SimTK::Vec3 across = SimTK::UnitVec3(SimTK::UnitVec3(line).perp());
    const auto tilted = [&](double degrees) {
        const double a = degrees * SimTK::Pi / 180;
        return std::cos(a) * line + std::sin(a) * across;
    };
    EXPECT_THROW(checkLoadResistible(pinch, makeTorque(tilted(4))), InputError);
    EXPECT_NO_THROW(checkLoadResistible(pinch, makeTorque(tilted(6))));
    // A force along the line, and any torque on the five-finger ball clutch, are fine.
    GraspCapacityRequest force = makeTorque(line);
    force.torque = false;
    EXPECT_NO_THROW(checkLoadResistible(pinch, force));
    EXPECT_NO_THROW(checkLoadResistible(scenario::findBuiltinScenario("ball-clutch"), makeTorque(SimTK::Vec3(0, 0, 1))));
}

// The default release along the ball's -x, where the thesis's box holds 14.0 N against full
// contact's 6.3 N (+122 %, docs/capacity.md): the approximation hands back when its reaction reaches
// the compliance model's -x side, and full contact, from there, decides the slip. Oracle: full
// contact's own ramp (the second method), same rate, stepper and accuracy; bound 10 %, the issue's
// criterion (measured +3.6 %: 6.53 N against 6.31 N).
TEST(GraspCapacity, ReleaseAtComplianceLimitsGivesFullContactsOnsetAlongBallMinusX) {
    // Above capacity the release witness hands back within a step of the load, so the slip-onset
    // time is full contact's within 10 % (measured 18.6 ms both; with only the 10 ms check it was
    // 28.2 ms, +51 %; the box alone never slips).
    expectBallCellAgrees(makeBallRamp(SimTK::Vec3(-1, 0, 0), "-x"), {"translation x", "compliance limit"}, 0.2);
}

// --release-at compliance along the phone's -y, where the compliance model lets go at a third of
// full contact's capacity (along the load's own direction at 0.58 N, the z side at 0.67 N; full
// contact 2.0 N): the figure must be full contact's own.
// Oracle: full contact's ramp from rest (the second method), same rate, stepper and accuracy;
// bound 10 %, the criterion (measured +1.0 %). The hand-back happens once: re-engaged
// during the give that follows it, where the contacts' wrench lags the load, the switch released
// again at the next check 9 times, the contacts took the load as a step at 1.04 N instead of
// 0.67 N, and the onset came at 1.61 N (-19 %; full contact under that step: 1.62 N).
TEST(GraspCapacity, ReleaseAtComplianceLimitsWellBeforeCapacityGivesFullContactsOnsetAlongPhoneMinusY) {
    const scenario::Scenario phone = scenario::findBuiltinScenario("phone-pinch");
    GraspCapacityRequest request;  // -y at the default rate, 1.96 N/s
    request.maxRampDuration = 1.5;
    simulation::ApproxOptions given;
    given.releaseTrigger = simulation::ApproxReleaseTrigger::Compliance;
    const RampPair ramps = measureFullAndApprox(phone, request, given);
    ASSERT_TRUE(bothSlipAfterAHandBack(ramps));
    const GraspCapacity& approx = ramps.approx;
    const CapacityFigures& f = ramps.full.trace.figures;
    const CapacityFigures& a = approx.trace.figures;
    EXPECT_NE(approx.trace.releaseReason.find("reached the compliance"), std::string::npos) << approx.trace.releaseReason;
    ASSERT_LT(a.releaseLoad, 0.5 * f.slipOnsetLoad) << "the release must come well before capacity for full contact to decide";
    for (const CapacitySample& s : approx.trace.samples) {
        if (s.time >= a.releaseTime) {
            EXPECT_EQ(s.engaged, 0) << "engaged again at t = " << s.time << " s";
        }
    }
    EXPECT_NEAR(a.slipOnsetLoad, f.slipOnsetLoad, 0.1 * f.slipOnsetLoad);
}

// The ball's +x: its compliance side once lay beyond the thesis's box (15.1 against 13.7 N), the
// clamped reaction could never reach it, and the witness released only when the reaction swung to
// the clamp's other side ("translation x +13.68 N", at 13.8 N); held at 1.25 x capacity, the
// penetration rule handed back at 11 ms and the onset came 17 % early. Such a side is now capped
// at the constraint's slip onset (GraspSwitchRelease.CapAtSlipOnset...; since the tangential stiffness is shared
// by normal force the model's side, 13.3 N, lies inside the box). Either way the release must name
// the loaded side (a negative reaction) and full contact decide the slip. Oracle: full contact,
// same rate, stepper and accuracy; bound 10 %, the criterion (measured +4.1 % on the ramp).
// On the bushing's rotational give, where it was found: the default's coupled give lets the ball
// shift toward a pad, and its penetration rule hands back first (-9.95 %, docs/capacity.md).
TEST(GraspCapacity, ReleaseOnTheLoadedSideAlongBallXGivesFullContactsOnsetRampAndHeld) {
    expectBallCellAgrees(makeBallRamp(SimTK::Vec3(1, 0, 0), "x"), {"translation x -"}, 0.1, simulation::ApproxBushingGive::Model);
}

// The ball pushed along -z (toward the palm) at 6 N/s: full contact's pads and fingers let it shift
// and turn, 2 mm at the goals by 7.5 N, long before it slides (about 16 N). The rotational give
// alone kept the translations stiff, and the approximation, engaged to its compliance limits at
// 8.5 N, slipped 2 mm at 8.8 N (+16 %). With the model's whole stiffness, rotations and translations
// coupled (the default), it shifts and turns as the model says. Oracle: full contact's own ramp (the
// second method), same rate, stepper and accuracy: within 10 %, the criterion (measured
// +1.4 %), and the rotational give outside it, which shows that the coupling is what closes the gap.
TEST(GraspCapacity, TheCoupledGiveFollowsFullContactsBallMinusZWhereTheRotationalGiveCannot) {
    const scenario::Scenario ball = scenario::findBuiltinScenario("ball-clutch");
    GraspCapacityRequest request = makeBallRamp(SimTK::Vec3(0, 0, -1), "-z");
    request.maxRampDuration = 1.6;  // past both onsets (1.26 and 1.47 s after the start)
    const RampPair coupled = measureFullAndApprox(ball, request, simulation::ApproxOptions{});
    ASSERT_TRUE(coupled.full.trace.figures.slipped);
    ASSERT_TRUE(coupled.approx.trace.figures.slipped);
    const double onset = coupled.full.trace.figures.slipOnsetLoad;
    EXPECT_NEAR(coupled.approx.trace.figures.slipOnsetLoad, onset, 0.1 * onset);
    // The same approximated ramp on the rotational give, against the full-contact ramp above.
    simulation::ApproxOptions rotationalGive;
    rotationalGive.bushingGive = simulation::ApproxBushingGive::Model;
    const GraspCapacity rotational = measureApproxRamp(ball, request, rotationalGive);
    ASSERT_TRUE(rotational.trace.figures.slipped);
    EXPECT_GT(rotational.trace.figures.slipOnsetLoad, 1.1 * onset);
}

// The ball turned about x at the default rate (0.177 N m/s, --direction all's torque rate: two object
// weights per second times the farthest goal's distance). Full contact's contacts creep under the
// growing torque, and it breaks loose at 0.173 N m, below the static compliance model's onset along
// the load (0.189 N m), where the static rules alone hand back after full contact has slipped. The
// creep watch follows the model in time with full contact's regularized friction and hands back at
// 0.176 N m. Oracle: full contact's own ramp (the second method), same rate, stepper and accuracy:
// within 10 % with the watch (measured +7.2 %), beyond it without (--release-creep off: +12.0 %),
// which shows that the watch is what closes the gap.
TEST(GraspCapacity, TheCreepWatchHandsBallTorqueXBackWhereTheStaticRulesComeTooLate) {
    const scenario::Scenario ball = scenario::findBuiltinScenario("ball-clutch");
    GraspCapacityRequest request = makeTorque(SimTK::Vec3(1, 0, 0));
    request.directionName = "x";
    request.rate = 0.1766523611734641;
    request.maxRampDuration = 1.25;  // past both onsets (0.98 and 1.10 s after the start)
    const RampPair watched = measureFullAndApprox(ball, request, simulation::ApproxOptions{});
    ASSERT_TRUE(bothSlipAfterAHandBack(watched));
    EXPECT_NE(watched.approx.trace.releaseReason.find("followed in time"), std::string::npos) << watched.approx.trace.releaseReason;
    const double onset = watched.full.trace.figures.slipOnsetLoad;
    EXPECT_NEAR(watched.approx.trace.figures.slipOnsetLoad, onset, 0.1 * onset);
    // The same approximated ramp without the watch, against the full-contact ramp above.
    simulation::ApproxOptions unwatched;
    unwatched.releaseCreep = false;
    const GraspCapacity staticOnly = measureApproxRamp(ball, request, unwatched);
    ASSERT_TRUE(staticOnly.trace.figures.slipped);
    ASSERT_TRUE(staticOnly.trace.figures.released);
    EXPECT_EQ(staticOnly.trace.releaseReason.find("followed in time"), std::string::npos) << staticOnly.trace.releaseReason;
    EXPECT_GT(staticOnly.trace.figures.slipOnsetLoad, 1.1 * onset);
}

// The ball turned about y at 6 N/s by the approximation with the bushing's rotational give
// (--bushing-give model): it gives about y as the grasp's compliance model says (10-12 N m/rad),
// and its locked fingers follow the turn. The
// witness hands back at 0.21 N m with the ball turned 0.019 rad, against full contact's 0.016 rad
// there. Before the fingers followed, full contact took back fingers that carried none of that turn,
// the ball turned as far again within 5 ms (slip 1.14 -> 2.07 mm) and the onset came at -18.9 %.
// Oracle: full contact's ramp (the second method), same rate, stepper and accuracy: onset within
// 10 %, the criterion (measured +5.1 %), and no jump of the slip over the 50 ms after the
// hand-back beyond 0.3 mm (measured: none, 1.16 mm at the release and at most 1.22 mm after).
TEST(GraspCapacity, TheGivesFollowingFingersHandTheBallsTurnBackWithoutAJump) {
    const scenario::Scenario ball = scenario::findBuiltinScenario("ball-clutch");
    GraspCapacityRequest request = makeTorque(SimTK::Vec3(0, 1, 0));
    // `--direction all --rate 6`: the forces' 6 N/s scaled by the default rates' ratio (a lever, m).
    request.rate = 6 * findDefaultRate(ball, true) / findDefaultRate(ball, false);
    request.maxRampDuration = 1.5;
    simulation::ApproxOptions given;
    given.bushingGive = simulation::ApproxBushingGive::Model;
    const RampPair ramps = measureFullAndApprox(ball, request, given);
    ASSERT_TRUE(bothSlipAfterAHandBack(ramps));
    const CapacityFigures& f = ramps.full.trace.figures;
    const CapacityFigures& a = ramps.approx.trace.figures;
    ASSERT_LT(a.releaseLoad, f.slipOnsetLoad) << "full contact must decide the onset";
    double atRelease = 0, after = 0;
    for (const CapacitySample& s : ramps.approx.trace.samples) {
        if (s.time <= a.releaseTime) atRelease = s.slip;
        if (s.time > a.releaseTime && s.time <= a.releaseTime + 0.05) after = std::max(after, s.slip);
    }
    EXPECT_GT(atRelease, 0.5e-3) << "the bushing must have given before the hand-back";
    EXPECT_LT(after - atRelease, 0.3e-3);
    EXPECT_NEAR(a.slipOnsetLoad, f.slipOnsetLoad, 0.1 * f.slipOnsetLoad);
}

// A step of 1.25 x full contact's ramp onset about the ball's x. The bushing that gives turns under
// a step before its reaction reaches the compliance limits: the reaction alone handed back 4 ms
// into the load and the ball slipped at 18.8 ms against full contact's 21.8 ms (-14 %). The
// trigger also sees the load the grasp carries (gravity and the external loads), which has reached
// the limits at the step itself. Oracle: full contact under the same step (the second method), same
// stepper and accuracy: handed back at the load's start (its sample there already released), and the onset time
// within 10 %, the criterion (measured 22.05 ms against 21.8, +1.1 %).
TEST(GraspCapacity, AStepBeyondTheLimitsIsHandedBackAtItsStartAboutBallX) {
    const scenario::Scenario ball = scenario::findBuiltinScenario("ball-clutch");
    GraspCapacityRequest request = makeTorque(SimTK::Vec3(1, 0, 0));
    request.maxRampDuration = 1.5;
    simulation::SimulationOptions options;
    options.integrator = simulation::IntegratorChoice::LinearlyImplicit;
    options.accuracy = 3e-4;
    const GraspCapacity ramp = measureGraspCapacityRamp(ball, options, request);
    ASSERT_TRUE(ramp.trace.figures.slipped);
    const double load = 1.25 * ramp.trace.figures.slipOnsetLoad;
    const GraspCapacity fullHeld = measureGraspCapacityConstant(ball, options, request, load, 0.1);
    options.mode = simulation::SimulationMode::Approx;
    const GraspCapacity approxHeld = measureGraspCapacityConstant(ball, options, request, load, 0.1);
    const OverloadFigures f = findOverloadFigures(fullHeld.trace.figures, fullHeld.start);
    const OverloadFigures a = findOverloadFigures(approxHeld.trace.figures, approxHeld.start);
    ASSERT_TRUE(f.slipped);
    ASSERT_TRUE(a.slipped);
    ASSERT_TRUE(a.released);
    EXPECT_LE(a.releaseTime, 1e-9);
    EXPECT_NE(approxHeld.trace.releaseReason.find("carried load"), std::string::npos) << approxHeld.trace.releaseReason;
    EXPECT_NEAR(a.slipOnsetTime, f.slipOnsetTime, 0.1 * f.slipOnsetTime);
}

// The deflected hand-back on the ball tripod's -y, where full contact's ball has given 1.9 mm and
// rolled 0.33 rad by the load of the release (0.72 N). Oracle: full contact's own ramp (the second
// method) at the first sample after the release: handed back engaged, the object is where the
// bushing held it (0.01 mm, 0.19 mm at the next sample); deflected, the compliance model's state must put it nearer to full
// contact's give in slip and in rotation (measured 1.17 mm and 0.26 rad), and full contact must
// keep it there rather than let it spring back (within 20 % 0.1 s later).
TEST(GraspCapacity, DeflectedHandBackStartsFullContactNearerItsOwnGiveOnTheTripod) {
    const scenario::Scenario tripod = scenario::findBuiltinScenario("ball-tripod");
    GraspCapacityRequest request;
    request.direction = SimTK::UnitVec3(0, -1, 0);
    request.directionName = "-y";
    request.maxRampDuration = 1.4;
    simulation::SimulationOptions options;
    options.integrator = simulation::IntegratorChoice::LinearlyImplicit;
    options.accuracy = 3e-4;
    const GraspCapacity full = measureGraspCapacityRamp(tripod, options, request);
    options.mode = simulation::SimulationMode::Approx;
    // The rotational give it was measured with: the default's coupled one already gives the ball
    // 0.79 mm of full contact's 2.0 mm by the release, where the deflection has less to add.
    options.approx.bushingGive = simulation::ApproxBushingGive::Model;
    const GraspCapacity engaged = measureGraspCapacityRamp(tripod, options, request);
    options.approx.handBack = simulation::ApproxHandBack::Deflected;
    const GraspCapacity deflected = measureGraspCapacityRamp(tripod, options, request);
    ASSERT_TRUE(deflected.trace.figures.released);
    EXPECT_NE(deflected.trace.releaseReason.find("handed back deflected by"), std::string::npos) << deflected.trace.releaseReason;
    const double t = deflected.trace.figures.releaseTime;
    const auto sampleAfter = [](const GraspCapacity& c, double time) {
        for (const CapacitySample& s : c.trace.samples) {
            if (s.time > time) return s;
        }
        return CapacitySample{};
    };
    const CapacitySample f = sampleAfter(full, t), e = sampleAfter(engaged, t), d = sampleAfter(deflected, t);
    ASSERT_GT(f.time, 0);
    EXPECT_LT(e.slip, 0.25 * f.slip);  // still near where the bushing held it
    EXPECT_LT(std::abs(d.slip - f.slip), 0.5 * std::abs(e.slip - f.slip)) << d.slip << " " << f.slip;
    EXPECT_LT(std::abs(d.rotation - f.rotation), 0.5 * std::abs(e.rotation - f.rotation)) << d.rotation << " " << f.rotation;
    const CapacitySample later = sampleAfter(deflected, d.time + 0.1);
    EXPECT_NEAR(later.slip, d.slip, 0.2 * d.slip);
}

// The anchor friction law on the error-controlled linearly implicit stepper, engaged under a
// growing load: the stepper's error estimate does not watch the anchors' states, which it
// integrates explicitly, and with the engaged approximation's long steps an anchor's sliding state
// blew up to infinity at t = 2.68 s (then NaN, and Simbody's "Inertia matrix contains a NaN").
// With the longest step capped at kAnchorStabilityLimit x the relaxation time, the ramp runs
// through, and follows CPodes's (the second method): the same engaged object to 2 um.
TEST(GraspCapacity, AnchorFrictionOnTheImplicitStepperFollowsCpodesUnderLoad) {
    scenario::Scenario ball = scenario::findBuiltinScenario("ball-clutch");
    ball.friction.model = contact::FrictionModel::Anchor;
    GraspCapacityRequest request;
    request.direction = SimTK::UnitVec3(1, 0, 0);
    request.directionName = "x";
    request.rate = 6;
    request.maxRampDuration = 1.8;  // to t = 2.9 s: 10.8 N, held engaged
    simulation::SimulationOptions options;
    options.mode = simulation::SimulationMode::Approx;
    options.accuracy = 3e-4;
    options.integrator = simulation::IntegratorChoice::LinearlyImplicit;
    // The rotational give the 2 um were measured with (the coupled default's ball gives 1.6 mm
    // here, where the two steppers differ by 3.7 um).
    options.approx.bushingGive = simulation::ApproxBushingGive::Model;
    const GraspCapacity implicit = measureGraspCapacityRamp(ball, options, request);
    options.integrator = simulation::IntegratorChoice::SimbodyCpodes;
    const GraspCapacity cpodes = measureGraspCapacityRamp(ball, options, request);
    EXPECT_EQ(implicit.trace.failure, "");
    ASSERT_EQ(cpodes.trace.failure, "");
    ASSERT_EQ(implicit.trace.samples.size(), cpodes.trace.samples.size());
    const CapacitySample& a = implicit.trace.samples.back();
    const CapacitySample& b = cpodes.trace.samples.back();
    EXPECT_NEAR(a.time, 2.9, 1e-9);
    EXPECT_EQ(a.engaged, 1);
    EXPECT_EQ(b.engaged, 1);
    EXPECT_NEAR(a.slip, b.slip, 2e-6) << a.slip << " " << b.slip;
}

// The planned key pinch loaded along +z under the capsule rule `deepest`: the key slips (0.75 N),
// pivots into the index finger's crease, and the middle phalanx lying flat on it has its one
// contact jump from end to end, with steps of 0.5-0.9 us. The ramp stops at the stall with the
// failure named (not hours later at its end), keeps the onset it measured, and its last sample is
// where the failure says the stepper stalled.
TEST(GraspCapacity, AStalledRampEndsThereWithTheFailureNamedAndKeepsItsOnset) {
    scenario::Scenario key = scenario::findBuiltinScenario("key-lateral");
    key.contact.capsuleContact = contact::CapsuleContact::Deepest;
    simulation::SimulationOptions options;
    options.accuracy = 3e-4;
    options.integrator = simulation::IntegratorChoice::LinearlyImplicit;
    GraspCapacityRequest request;
    request.direction = SimTK::UnitVec3(0, 0, 1);
    request.directionName = "z";
    const GraspCapacity c = measureGraspCapacityRamp(key, options, request);
    ASSERT_NE(c.trace.failure.find("the integrator stalled"), std::string::npos) << c.trace.failure;
    EXPECT_TRUE(c.trace.figures.slipped);
    EXPECT_FALSE(c.trace.figures.dropped);
    ASSERT_FALSE(c.trace.samples.empty());
    const double last = c.trace.samples.back().time;
    EXPECT_LT(last, c.start + 4.0);  // before the ramp's end (maxDuration)
    const std::string between = "between t = ";
    const std::size_t at = c.trace.failure.find(between);
    ASSERT_NE(at, std::string::npos);
    EXPECT_NEAR(std::stod(c.trace.failure.substr(at + between.size())), last, 1e-9) << c.trace.failure;
}

}  // namespace
}  // namespace graspsim::capacity
