#include "graspsim/system/passive_joint_forces.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "graspsim/system/multibody_model.h"
#include "pendulum_models.h"

namespace graspsim::system {
namespace {

using test::makePendulum;
using test::PendulumParameters;

// A measured value for the test report (RecordProperty would round a double to an integer).
std::string toText(double value) {
    std::ostringstream text;
    text << std::setprecision(3) << value;
    return text.str();
}

// A pendulum joint with the given passive properties; Revolute when limits are wanted.
model::ModelDescription makePassivePendulum(const PendulumParameters& p, double stiffness,
                                            double restAngle, double damping) {
    model::ModelDescription m = makePendulum(p);
    model::Joint& joint = m.joints.front();
    joint.stiffness = stiffness;
    joint.restAngle = restAngle;
    joint.damping = damping;
    return m;
}

void setLimits(model::ModelDescription& m, double lower, double upper) {
    model::Joint& joint = m.joints.front();
    joint.type = model::Joint::Type::Revolute;
    joint.lower = lower;
    joint.upper = upper;
}

// Samples of an integrated run: time, energy, dissipation power, angle.
struct Samples {
    std::vector<double> time, energy, dissipation, angle;
};

Samples integrate(const MultibodyModel& model, const SimTK::State& initial, double duration,
                  double interval, double accuracy) {
    SimTK::RungeKuttaMersonIntegrator integrator(model.getSystem());
    integrator.setAccuracy(accuracy);
    integrator.initialize(initial);
    Samples run;
    const int steps = static_cast<int>(std::lround(duration / interval));
    for (int i = 0; i <= steps; ++i) {
        integrator.stepTo(i * interval);
        const SimTK::State& state = integrator.getState();
        model.getSystem().realize(state, SimTK::Stage::Dynamics);
        run.time.push_back(state.getTime());
        run.energy.push_back(model.calcMechanicalEnergy(state));
        run.dissipation.push_back(model.calcPassiveDissipationPower(state));
        run.angle.push_back(model.getJointPosition(state, "pivot"));
    }
    return run;
}

// Largest relative mismatch over the run between E(0) - E(t) and the trapezoid integral of
// the dissipation power, relative to the total energy lost.
double calcEnergyBalanceError(const Samples& run) {
    double dissipated = 0, worst = 0;
    for (std::size_t i = 1; i < run.time.size(); ++i) {
        dissipated +=
            0.5 * (run.dissipation[i] + run.dissipation[i - 1]) * (run.time[i] - run.time[i - 1]);
        worst = std::max(worst, std::abs((run.energy.front() - run.energy[i]) - dissipated));
    }
    return worst / (run.energy.front() - run.energy.back());
}

// Largest increase of energy between consecutive samples, relative to |E(0)|.
double calcLargestEnergyRise(const Samples& run) {
    double rise = 0;
    for (std::size_t i = 1; i < run.energy.size(); ++i)
        rise = std::max(rise, run.energy[i] - run.energy[i - 1]);
    return rise / std::abs(run.energy.front());
}

TEST(PassiveJointForces, DampedSpringPendulumLosesExactlyWhatItDissipates) {
    MultibodyModel model(makePassivePendulum({}, 2.0, 0.3, 0.05));
    SimTK::State state = model.realizeTopology();
    model.setJointPosition(state, "pivot", 1.2);

    const Samples run = integrate(model, state, 4.0, 1e-3, 1e-10);
    RecordProperty("largest_energy_rise", toText(calcLargestEnergyRise(run)));
    RecordProperty("energy_balance_error", toText(calcEnergyBalanceError(run)));

    EXPECT_LT(calcLargestEnergyRise(run), 1e-9);
    EXPECT_LT(calcEnergyBalanceError(run), 0.005);
    EXPECT_GT(run.energy.front() - run.energy.back(), 1.0)
        << "about 2 J of 7 J should be dissipated";
}

// A finger-sized segment (20 g, 2 cm) falls from inside its range onto its lower limit under
// gravity. Oracle for the overshoot x past the limit: energy only decreases, so the stop can
// store at most what gravity released, k x^2 / 2 <= m g l (1 - cos q0) (with cos <= 1 at the
// limit side), giving x <= sqrt(2 m g l (1 - cos q0) / k).
TEST(PassiveJointForces, StopHoldsAFallingSegmentWithinTheEnergyBound) {
    PendulumParameters finger;
    finger.mass = 0.02;
    finger.length = 0.02;
    finger.centralIzz = 1e-6;
    model::ModelDescription m = makePassivePendulum(finger, 0, 0, 0);
    setLimits(m, 0.5, 2.0);
    const SystemOptions options;
    MultibodyModel model(m, options);
    SimTK::State state = model.realizeTopology();
    const double q0 = 1.5;
    model.setJointPosition(state, "pivot", q0);

    const Samples run = integrate(model, state, 1.0, 1e-4, 1e-8);

    const double mgl = finger.mass * 9.81 * finger.length;
    const double bound = std::sqrt(2 * mgl * (1 - std::cos(q0)) / options.stopStiffness);
    const double lowest = *std::min_element(run.angle.begin(), run.angle.end());
    RecordProperty("overshoot_rad", toText(0.5 - lowest));
    RecordProperty("overshoot_bound_rad", toText(bound));
    RecordProperty("final_angle_rad", toText(run.angle.back()));
    EXPECT_GE(lowest, 0.5 - bound);
    EXPECT_LT(bound, SimTK::convertDegreesToRadians(1.0))
        << "documented: finger overshoot < 1 degree";
    // At rest the stop carries gravity's torque m g l sin(q) alone.
    const double sag = mgl * std::sin(0.5) / options.stopStiffness;
    EXPECT_NEAR(run.angle.back(), 0.5 - sag, 0.05 * sag);
}

// The same impact with an undamped pendulum: the stop's energy and dissipation must account
// for every joule, including during contact where the clamped Hunt-Crossley force acts.
TEST(PassiveJointForces, StopContactKeepsTheEnergyBalance) {
    model::ModelDescription m = makePassivePendulum({}, 0, 0, 0);
    setLimits(m, -0.2, 0.4);
    SystemOptions options;
    options.stopStiffness = 200;
    options.stopDissipation = 0.5;
    MultibodyModel model(m, options);
    SimTK::State state = model.realizeTopology();
    model.setJointPosition(state, "pivot", 0.35);
    model.setJointSpeed(state, "pivot", 2.0);

    const Samples run = integrate(model, state, 2.0, 1e-4, 1e-9);
    RecordProperty("largest_energy_rise", toText(calcLargestEnergyRise(run)));
    RecordProperty("energy_balance_error", toText(calcEnergyBalanceError(run)));
    RecordProperty("energy_lost", toText(run.energy.front() - run.energy.back()));

    EXPECT_LT(calcLargestEnergyRise(run), 1e-9);
    EXPECT_LT(calcEnergyBalanceError(run), 0.005);
    EXPECT_GT(run.energy.front() - run.energy.back(), 0.01) << "the stops should have dissipated";
}

// The documented claim for SystemOptions::stopStiffness: a finger joint whose spring pulls
// 1.6 rad past its upper limit (0.25 N m/rad) rests within 1 degree of the limit.
TEST(PassiveJointForces, DefaultStopKeepsFingerSpringLoadWithinOneDegree) {
    PendulumParameters finger;
    finger.mass = 0.02;
    finger.length = 0.02;
    finger.centralIzz = 1e-6;
    model::ModelDescription m = makePassivePendulum(finger, 0.25, 1.6 + 1.2, 0.05);
    setLimits(m, -0.3, 1.2);
    MultibodyModel model(m);
    SimTK::State state = model.realizeTopology();

    const Samples run = integrate(model, state, 0.5, 1e-3, 1e-7);

    const double highest = *std::max_element(run.angle.begin(), run.angle.end());
    RecordProperty("overshoot_rad", toText(highest - 1.2));
    RecordProperty("final_overshoot_rad", toText(run.angle.back() - 1.2));
    EXPECT_LT(highest - 1.2, SimTK::convertDegreesToRadians(1.0));
    EXPECT_GT(highest, 1.2) << "the spring should press the joint onto its limit";
}

// Direct check of one joint's forces against Simbody's documented laws at hand-picked states.
class PassiveJointForcesAtState : public ::testing::Test {
protected:
    PassiveJointForcesAtState() : model_(makeModel(), makeOptions()) {}

    static model::ModelDescription makeModel() {
        model::ModelDescription m = makePassivePendulum({}, kSpring, kRest, kDamping);
        setLimits(m, kLower, kUpper);
        return m;
    }
    static SystemOptions makeOptions() {
        SystemOptions options;
        options.stopStiffness = kStop;
        options.stopDissipation = kStopDissipation;
        return options;
    }
    SimTK::State makeState(double q, double u) const {
        SimTK::State state = model_.getSystem().getDefaultState();
        model_.setJointPosition(state, "pivot", q);
        model_.setJointSpeed(state, "pivot", u);
        model_.getSystem().realize(state, SimTK::Stage::Dynamics);
        return state;
    }

    static constexpr double kSpring = 3, kRest = 0.2, kDamping = 0.1;
    static constexpr double kLower = -0.5, kUpper = 0.8, kStop = 40, kStopDissipation = 2;
    MultibodyModel model_;
};

TEST_F(PassiveJointForcesAtState, InsideTheRangeOnlySpringAndDamperAct) {
    const SimTK::State state = makeState(0.5, -1.5);
    const PassiveJointForces& forces = model_.getPassiveJointForces("pivot");

    EXPECT_TRUE(forces.hasSpring() && forces.hasDamper() && forces.hasStop());
    EXPECT_NEAR(forces.calcGeneralizedForce(state), -kSpring * (0.5 - kRest) + kDamping * 1.5,
                1e-14);
    EXPECT_NEAR(forces.calcPotentialEnergy(state), 0.5 * kSpring * 0.3 * 0.3, 1e-14);
    EXPECT_NEAR(forces.calcDissipationPower(state), kDamping * 1.5 * 1.5, 1e-14);
}

TEST_F(PassiveJointForcesAtState, PastTheUpperLimitTheStopAddsHuntCrossleyForce) {
    const double x = 0.05, u = 0.3;
    const SimTK::State state = makeState(kUpper + x, u);
    const PassiveJointForces& forces = model_.getPassiveJointForces("pivot");

    const double stopForce = -kStop * x * (1 + kStopDissipation * u);
    EXPECT_NEAR(forces.calcGeneralizedForce(state),
                -kSpring * (kUpper + x - kRest) - kDamping * u + stopForce, 1e-12);
    EXPECT_NEAR(forces.calcPotentialEnergy(state),
                0.5 * kSpring * std::pow(kUpper + x - kRest, 2) + 0.5 * kStop * x * x, 1e-12);
    EXPECT_NEAR(forces.calcDissipationPower(state),
                kDamping * u * u + kStop * x * kStopDissipation * u * u, 1e-12);
}

TEST_F(PassiveJointForcesAtState, FastReboundClampsTheStopAtZeroAndItStillDissipates) {
    const double x = 0.05, u = -1.0;  // 1 + d u < 0: Simbody clamps the stop force to zero
    const SimTK::State state = makeState(kUpper + x, u);
    const PassiveJointForces& forces = model_.getPassiveJointForces("pivot");

    EXPECT_NEAR(forces.calcGeneralizedForce(state), -kSpring * (kUpper + x - kRest) - kDamping * u,
                1e-12);
    // The elastic -k x the stop would have pushed with is lost: power -(0 - (-k x)) u = -k x u.
    EXPECT_NEAR(forces.calcDissipationPower(state), kDamping * u * u - kStop * x * u, 1e-12);
}

TEST_F(PassiveJointForcesAtState, PastTheLowerLimitTheStopPushesUp) {
    const double x = -0.04, u = -0.5;
    const SimTK::State state = makeState(kLower + x, u);
    const PassiveJointForces& forces = model_.getPassiveJointForces("pivot");

    const double stopForce = -kStop * x * (1 - kStopDissipation * u);
    EXPECT_GT(stopForce, 0);
    EXPECT_NEAR(forces.calcGeneralizedForce(state),
                -kSpring * (kLower + x - kRest) - kDamping * u + stopForce, 1e-12);
    EXPECT_NEAR(forces.calcDissipationPower(state),
                kDamping * u * u + kStop * std::abs(x) * kStopDissipation * u * u, 1e-12);
}

TEST(PassiveJointForces, ZeroCoefficientsAndDisabledLimitsCreateNoElements) {
    model::ModelDescription m = makePassivePendulum({}, 0, 0, 0);
    setLimits(m, -1, 1);
    SystemOptions options;
    options.enforceLimits = false;
    MultibodyModel model(m, options);

    const PassiveJointForces& forces = model.getPassiveJointForces("pivot");

    EXPECT_FALSE(forces.hasSpring());
    EXPECT_FALSE(forces.hasDamper());
    EXPECT_FALSE(forces.hasStop());
    EXPECT_EQ(model.getForces().getNumForces(), 1) << "gravity only";
}

}  // namespace
}  // namespace graspsim::system
