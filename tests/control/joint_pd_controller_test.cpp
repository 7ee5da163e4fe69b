#include "graspsim/control/joint_pd_controller.h"

#include "graspsim/error.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace graspsim;

namespace {

// A pendulum: a 1 kg point-like mass 0.5 m below a pin about z, no passive forces.
model::ModelDescription pendulum() {
    model::ModelDescription m;
    m.name = "pendulum";
    model::Body base;
    base.name = "base";
    model::Body bob;
    bob.name = "bob";
    bob.mass = 1.0;
    bob.p_BCm = {0, -0.5, 0};
    bob.inertia = {1e-4, 1e-4, 1e-4};
    m.bodies = {base, bob};
    model::Joint pin;
    pin.name = "pin";
    pin.type = model::Joint::Type::Continuous;
    pin.parent = "base";
    pin.child = "bob";
    m.joints = {pin};
    return m;
}

}  // namespace

// Oracle: the PD law with gravity compensation, tau = kp (q* - q) - kd u + m g l sin(q).
TEST(JointPdController, AppliesThePdLawPlusTheGravityHoldingTorque) {
    system::MultibodyModel model(pendulum());
    control::JointPdController pd(model, {{"pin", {20.0, 2.0}}}, {"bob"});
    SimTK::State s = model.realizeTopology();
    pd.setTargets(s, SimTK::Vector(1, 0.3));
    model.setJointPosition(s, "pin", 0.5);
    model.setJointSpeed(s, "pin", -0.4);
    model.getSystem().realize(s, SimTK::Stage::Acceleration);
    // M udot = tau_pd + tau_gravity, and gravity's torque is exactly cancelled by the holding term.
    const double I = 1.0 * 0.25 + 1e-4;
    const double expected = (20.0 * (0.3 - 0.5) - 2.0 * (-0.4)) / I;
    EXPECT_NEAR(s.getUDot()[0], expected, 1e-9);
}

TEST(JointPdController, SettlesOnTheTargetUnderGravity) {
    system::MultibodyModel model(pendulum());
    control::JointPdController pd(model, {{"pin", {5.0, 1.0}}}, {"bob"});
    SimTK::State s = model.realizeTopology();
    pd.setTargets(s, SimTK::Vector(1, 1.2));
    SimTK::RungeKuttaMersonIntegrator integrator(model.getSystem());
    integrator.setAccuracy(1e-8);
    SimTK::TimeStepper stepper(model.getSystem(), integrator);
    stepper.initialize(s);
    stepper.stepTo(10.0);
    // Without compensation the bob would hang at q with 5 (1.2 - q) = m g l sin q, i.e. q ~ 0.5.
    EXPECT_NEAR(model.getJointPosition(stepper.getState(), "pin"), 1.2, 1e-6);
}

// Oracle: the smoothstep in closed form. A ramp planned after a delay leaves the targets as they
// were until it starts (what lets an integrator that is ahead go on), then follows
// a + (b - a)(3 tau^2 - 2 tau^3); a second ramp starts where the first ends.
TEST(JointPdController, RampsTargetsAlongASmoothstepAfterTheDelay) {
    system::MultibodyModel model(pendulum());
    control::JointPdController pd(model, {{"pin", {5.0, 1.0}}}, {"bob"});
    SimTK::State s = model.realizeTopology();
    pd.setTargets(s, SimTK::Vector(1, 0.2));
    s.updTime() = 1.0;
    pd.rampTargets(s, SimTK::Vector(1, 0.6), 0.01, 0.01);  // from 0.2 over [1.01, 1.02]
    pd.rampTargets(s, SimTK::Vector(1, 1.0), 0.01, 0.005);  // queued: over [1.02, 1.03]
    const auto targetAt = [&](double t) {
        s.updTime() = t;
        return pd.getTargets(s)[0];
    };
    EXPECT_DOUBLE_EQ(targetAt(1.0), 0.2);
    EXPECT_DOUBLE_EQ(targetAt(1.01), 0.2);
    const double tau = 0.3;
    EXPECT_NEAR(targetAt(1.01 + tau * 0.01), 0.2 + 0.4 * (3 * tau * tau - 2 * tau * tau * tau), 1e-12);
    EXPECT_NEAR(targetAt(1.02), 0.6, 1e-12);
    EXPECT_NEAR(targetAt(1.025), 0.8, 1e-12);  // the smoothstep's midpoint
    EXPECT_NEAR(targetAt(2.0), 1.0, 1e-12);
    EXPECT_THROW(pd.rampTargets(s, SimTK::Vector(1, 1.0), 0.0, 0.01), Error);
}

TEST(JointPdController, UnknownJointIsNamed) {
    system::MultibodyModel model(pendulum());
    EXPECT_THROW(control::JointPdController(model, {{"elbow", {1, 1}}}, {}), InputError);
}
