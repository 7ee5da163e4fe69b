#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "contact_scenes.h"
#include "graspsim/contact/compliant_contact_force.h"

// The force element integrated in Simbody against closed-form physics: static Hertz depth,
// energy conservation through a bounce, and two-contact friction on a squeezed box (the case
// where HuntCrossleyForce would lose contacts).

namespace graspsim::contact {
namespace {

using SimTK::Vec3;
using test::Scene;

constexpr double kG = 9.81;  // m/s^2

// A measured value for the test report (RecordProperty would round a double to an integer).
std::string toText(double value) {
    std::ostringstream text;
    text << std::setprecision(6) << value;
    return text.str();
}

// A ball on a floor: radius 45 mm, 200 g (the ball object), on a vertical Slider or Free.
struct BallOnFloor {
    static constexpr double kMass = 0.2, kRadius = 0.045, kEStar = 1e6;
    Scene scene;
    SimTK::Force::Gravity gravity{scene.forces, scene.matter, Vec3(0, -kG, 0)};
    SimTK::MobilizedBody ball;
    CompliantContactForce force;

    BallOnFloor(bool free, double dissipation) {
        ball = free ? SimTK::MobilizedBody(scene.addFree(kMass, kRadius))
                    : SimTK::MobilizedBody(scene.addSlider(SimTK::YAxis, kMass, kRadius));
        const ContactParameters m = test::makeParameters(kEStar, dissipation);
        force = CompliantContactForce(
            scene.forces, {{test::makeSurface(ball, "ball", ContactShape::sphere(kRadius)),
                            scene.makeFloor(), m}});
    }
    double calcHeight(const SimTK::State& s) const { return ball.getBodyOriginLocation(s)[1]; }
};

TEST(CompliantContactDynamics, BallOnFloorSettlesAtStaticHertzDepth) {
    // Damped (c = 20 s/m, about 0.7 of critical at the rest depth) so it settles within 0.3 s.
    BallOnFloor s(false, 20);
    SimTK::State state = s.scene.system.realizeTopology();
    s.ball.setOneQ(state, 0, BallOnFloor::kRadius);  // touching, at rest
    SimTK::RungeKuttaMersonIntegrator integrator(s.scene.system);
    integrator.setAccuracy(1e-8);
    SimTK::TimeStepper stepper(s.scene.system, integrator);
    stepper.initialize(state);
    stepper.stepTo(0.3);
    const double depth = BallOnFloor::kRadius - s.calcHeight(integrator.getState());
    const double expected = test::calcStaticHertzDepth(BallOnFloor::kMass * kG, BallOnFloor::kEStar,
                                                       BallOnFloor::kRadius);
    RecordProperty("depth_um", toText(depth * 1e6));
    EXPECT_NEAR(depth, expected, 0.01 * expected);  // 0.36 mm
}

TEST(CompliantContactDynamics, UndampedBounceConservesEnergy) {
    // Free ball dropped from 20 mm above the floor, drifting sideways, no dissipation, no
    // friction: kinetic + gravity + elastic Hertz energy stays constant through the bounce.
    BallOnFloor s(true, 0);
    SimTK::State state = s.scene.system.realizeTopology();
    s.scene.system.realizeModel(state);
    s.ball.setQToFitTranslation(state, Vec3(0, BallOnFloor::kRadius + 0.02, 0));
    s.ball.setUToFitLinearVelocity(state, Vec3(0.1, 0, 0.05));
    SimTK::RungeKuttaMersonIntegrator integrator(s.scene.system);
    integrator.setAccuracy(1e-10);
    SimTK::TimeStepper stepper(s.scene.system, integrator);
    stepper.initialize(state);
    s.scene.system.realize(integrator.getState(), SimTK::Stage::Dynamics);
    const double e0 = s.scene.system.calcEnergy(integrator.getState());
    double worst = 0, lowest = 1, elasticPeak = 0;
    for (int i = 1; i <= 150; ++i) {  // 0.15 s: falls in 64 ms, bounces back up
        stepper.stepTo(i * 1e-3);
        const SimTK::State& si = integrator.getState();
        s.scene.system.realize(si, SimTK::Stage::Dynamics);
        worst = std::max(worst, std::abs(s.scene.system.calcEnergy(si) - e0) / e0);
        lowest = std::min(lowest, s.calcHeight(si));
        elasticPeak = std::max(elasticPeak, s.force.calcPotentialEnergyContribution(si));
    }
    RecordProperty("relative_energy_error", toText(worst));
    EXPECT_LT(lowest, BallOnFloor::kRadius);  // it did hit the floor
    EXPECT_GT(elasticPeak, 0.01);             // and stored a good part of its 39 mJ there
    EXPECT_LT(worst, 1e-4);
}

// A 1 kg box free to slide along y (gravity off), squeezed along x between two 10 mm spheres,
// each on an x Slider pushed toward the box with a constant N = 10 N, and pulled along y by a
// constant force F. The friction of the two contacts together resists the pull.
struct SqueezedBox {
    static constexpr double kBoxMass = 1, kSqueeze = 10, kRadius = 0.01, kEStar = 1e6;
    static constexpr double kHalfWidth = 0.02, kTransition = 1e-3;
    Scene scene;
    SimTK::MobilizedBody::Slider box = scene.addSlider(SimTK::YAxis, kBoxMass, 0.05);
    SimTK::MobilizedBody::Slider left = scene.addSlider(SimTK::XAxis, 0.05, kRadius);
    SimTK::MobilizedBody::Slider right = scene.addSlider(SimTK::XAxis, 0.05, kRadius);
    CompliantContactForce force;
    SimTK::State state;

    SqueezedBox(double pull, double staticFriction, double dynamicFriction) {
        SimTK::Force::MobilityConstantForce(scene.forces, left, 0, kSqueeze);
        SimTK::Force::MobilityConstantForce(scene.forces, right, 0, -kSqueeze);
        SimTK::Force::MobilityConstantForce(scene.forces, box, 0, pull);
        const ContactParameters m =
            test::makeParameters(kEStar, 5, staticFriction, dynamicFriction, kTransition);
        const ContactShape boxShape = ContactShape::box(Vec3(kHalfWidth, 0.05, 0.02));
        const ContactSurface boxSurface = test::makeSurface(box, "box", boxShape);
        const ContactShape ball = ContactShape::sphere(kRadius);
        force = CompliantContactForce(scene.forces,
                                      {{test::makeSurface(left, "left", ball), boxSurface, m},
                                       {test::makeSurface(right, "right", ball), boxSurface, m}});
        state = scene.system.realizeTopology();
        // Start at the static depth for N, so the squeeze is in equilibrium from the start.
        const double depth = test::calcStaticHertzDepth(kSqueeze, kEStar, kRadius);
        left.setOneQ(state, 0, -(kHalfWidth + kRadius - depth));
        right.setOneQ(state, 0, kHalfWidth + kRadius - depth);
    }
};

// The box's position and speed along y after integrating to each of the given times.
std::vector<std::pair<double, double>> integrateBox(SqueezedBox& s,
                                                    const std::vector<double>& times) {
    SimTK::RungeKuttaMersonIntegrator integrator(s.scene.system);
    integrator.setAccuracy(1e-7);
    SimTK::TimeStepper stepper(s.scene.system, integrator);
    stepper.initialize(s.state);
    std::vector<std::pair<double, double>> samples;
    for (double t : times) {
        stepper.stepTo(t);
        const SimTK::State& st = integrator.getState();
        samples.emplace_back(s.box.getOneQ(st, 0), s.box.getOneU(st, 0));
    }
    return samples;
}

TEST(CompliantContactDynamics, SqueezedBoxSlidesWithTwoContactsOfDynamicFriction) {
    // mu_s = mu_d = 0.5: friction is exactly mu_d f_n per contact once slip exceeds v_tr.
    // F = 14 N > 2 mu_d N = 10 N: a = (14 - 10) / 1 kg = 4 m/s^2 (9 m/s^2 if one contact
    // were dropped).
    SqueezedBox s(14, 0.5, 0.5);
    const auto samples = integrateBox(s, {0.02, 0.05});
    const double a = (samples[1].second - samples[0].second) / 0.03;
    RecordProperty("acceleration", toText(a));
    EXPECT_NEAR(a, (14 - 2 * 0.5 * SqueezedBox::kSqueeze) / SqueezedBox::kBoxMass, 0.05 * 4);
    s.scene.system.realize(s.state, SimTK::Stage::Velocity);
    EXPECT_EQ(s.force.findContactReports(s.state).size(), 2u);
}

TEST(CompliantContactDynamics, SqueezedBoxHeldBelowTheFrictionLimitOnlyCreeps) {
    // F = 8 N < 2 mu_s N = 10 N. Regularized friction has no stiction: the box creeps at the
    // speed where both contacts together carry F, v = v_tr F / (2 mu_d N) = 0.8 mm/s (exact
    // for mu_s = mu_d, below v_tr). Documented bound: creep over 1 s below v_tr F / (2 mu N) * 1 s.
    SqueezedBox s(8, 0.5, 0.5);
    const double creepSpeed = SqueezedBox::kTransition * 8 / (2 * 0.5 * SqueezedBox::kSqueeze);
    const auto samples = integrateBox(s, {1.0});
    RecordProperty("creep_mm", toText(samples[0].first * 1e3));
    EXPECT_LE(samples[0].first, creepSpeed * 1.0 * (1 + 1e-3));
    EXPECT_GE(samples[0].first, creepSpeed * 1.0 * 0.95);  // not 1.6 mm: both contacts hold
}

TEST(CompliantContactDynamics, StaticFrictionAboveDynamicHoldsBelowItsLimit) {
    // mu_s = 0.8, mu_d = 0.5, F = 14 N < 2 mu_s N = 16 N: creep below v_tr (where mu peaks).
    SqueezedBox held(14, 0.8, 0.5);
    const auto slow = integrateBox(held, {0.5, 1.0});
    EXPECT_LT(slow[1].second, SqueezedBox::kTransition);
    EXPECT_LT(slow[1].first - slow[0].first, 0.5 * SqueezedBox::kTransition);
    // F = 17 N > 16 N: it breaks away and accelerates toward (17 - 2 mu_d N) / m = 7 m/s^2.
    SqueezedBox sliding(17, 0.8, 0.5);
    const auto fast = integrateBox(sliding, {0.04, 0.05});
    EXPECT_NEAR((fast[1].second - fast[0].second) / 0.01, 7, 0.05 * 7);
}

// Switches pair 0 off at a scheduled time, as the grasp approximation will.
class DisablePairAt : public SimTK::ScheduledEventHandler {
public:
    DisablePairAt(const CompliantContactForce& force, double time) : force_(force), time_(time) {}
    SimTK::Real getNextEventTime(const SimTK::State&, bool includeCurrentTime) const override {
        return includeCurrentTime ? time_ : SimTK::Infinity;
    }
    void handleEvent(SimTK::State& state, SimTK::Real, bool&) const override {
        force_.setPairEnabled(state, 0, false);
    }

private:
    CompliantContactForce force_;
    double time_;
};

TEST(CompliantContactDynamics, PairSwitchedOffInAnEventHandlerStopsCarryingTheBall) {
    BallOnFloor s(false, 20);
    s.scene.system.addEventHandler(new DisablePairAt(s.force, 0.3));
    SimTK::State state = s.scene.system.realizeTopology();
    s.ball.setOneQ(state, 0, BallOnFloor::kRadius);
    SimTK::RungeKuttaMersonIntegrator integrator(s.scene.system);
    integrator.setAccuracy(1e-8);
    SimTK::TimeStepper stepper(s.scene.system, integrator);
    stepper.initialize(state);
    stepper.stepTo(0.3);
    const double resting = s.calcHeight(integrator.getState());
    stepper.stepTo(0.4);
    // At rest (to ~1e-9 m/s after settling) at 0.3 s, then free fall for 0.1 s.
    EXPECT_NEAR(s.calcHeight(integrator.getState()), resting - 0.5 * kG * 0.1 * 0.1, 1e-6);
    EXPECT_FALSE(s.force.isPairEnabled(integrator.getState(), 0));
}

}  // namespace
}  // namespace graspsim::contact
