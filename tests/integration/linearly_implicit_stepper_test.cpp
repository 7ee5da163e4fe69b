// The linearly implicit stepper against closed forms: a free fall (Euler: the scheme's exact
// discrete solution and first-order convergence; ROS2: exact), a stiff overdamped spring-damper
// (stable at 5-20x the explicit limit; first- and second-order convergence to the analytic
// solution), and, as a second method, Runge-Kutta-Merson on a double pendulum (error control).
// At fixed steps, a damper left explicit against the closed form of ROS2 on it: stable steps run
// through, unstable ones stop where the closed-form error estimate exceeds the state's scale.
// Bad options throw.

#include "graspsim/integration/linearly_implicit_stepper.h"

#include "graspsim/error.h"
#include "graspsim/integration/fixed_step_too_long_error.h"
#include "graspsim/integration/joint_impedance_jacobian.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace graspsim::integration {
namespace {

constexpr double kG = 9.81;  // m/s^2

// One body on a vertical Slider (q = height, m), with optional gravity, spring and damper.
struct SliderScene {
    SimTK::MultibodySystem system;
    SimTK::SimbodyMatterSubsystem matter{system};
    SimTK::GeneralForceSubsystem forces{system};
    SimTK::MobilizedBody::Slider body;

    SliderScene(double mass, double gravity)
        : body(matter.updGround(), SimTK::Transform(SimTK::Rotation(SimTK::UnitVec3(SimTK::YAxis), SimTK::XAxis)),
               SimTK::Body::Rigid(SimTK::MassProperties(mass, SimTK::Vec3(0), SimTK::Inertia(1e-6))),
               SimTK::Transform(SimTK::Rotation(SimTK::UnitVec3(SimTK::YAxis), SimTK::XAxis))) {
        if (gravity != 0) SimTK::Force::Gravity(forces, matter, SimTK::Vec3(0, -gravity, 0));
    }
};

double fallTo(double h, double duration, double& discreteOracle, int order = 1) {
    SliderScene scene(0.1, kG);
    SimTK::State state = scene.system.realizeTopology();
    LinearlyImplicitOptions options;
    options.stepSize = h;
    options.order = order;
    LinearlyImplicitStepper stepper(scene.system, {}, options);
    stepper.initialize(state);
    stepper.stepTo(duration);
    const double n = std::round(duration / h);
    discreteOracle = -kG * h * h * n * (n + 1) / 2;  // u_k = -g k h, y_k = sum h u_j
    return scene.body.getOneQ(stepper.getState(), 0);
}

TEST(LinearlyImplicitStepper, FreeFallIsExactWithRosenbrock) {
    double unused = 0;
    EXPECT_NEAR(fallTo(1e-2, 0.5, unused, 2), -0.5 * kG * 0.25, 1e-12);  // second order: exact on a parabola
}

TEST(LinearlyImplicitStepper, NamesItsMethodByOrder) {
    SliderScene scene(0.1, kG);
    LinearlyImplicitOptions options;
    options.order = 1;
    EXPECT_EQ(LinearlyImplicitStepper(scene.system, {}, options).getMethodName(), "linearly-implicit-euler");
    options.order = 2;
    EXPECT_EQ(LinearlyImplicitStepper(scene.system, {}, options).getMethodName(), "rosenbrock-ros2");
}

TEST(LinearlyImplicitStepper, FreeFallIsSymplecticEulerAndFirstOrder) {
    const double T = 0.5;
    double previousError = 0;
    for (double h : {2e-3, 1e-3, 5e-4}) {
        double discrete = 0;
        const double y = fallTo(h, T, discrete);
        EXPECT_NEAR(y, discrete, 1e-12);
        const double error = std::abs(y - (-0.5 * kG * T * T));
        EXPECT_NEAR(error, 0.5 * kG * h * T, 1e-12);  // the scheme's exact error, g h t / 2
        if (previousError > 0) {
            EXPECT_NEAR(previousError / error, 2.0, 1e-6);
        }
        previousError = error;
    }
}

// m x'' + c x' + k x = 0 with m = 1 g, c = 10 N s/m, k = 100 N/m: time constants m/c = 0.1 ms
// (fast) and c/k = 0.1 s (slow). Explicit Euler needs h < 2 m / c = 0.2 ms.
struct StiffDamper {
    static constexpr double kMass = 1e-3, kDamping = 10, kStiffness = 100, kStart = 0.01;
    SliderScene scene{kMass, 0};
    SimTK::Force::MobilityLinearSpring spring{scene.forces, scene.body, SimTK::MobilizerQIndex(0), kStiffness, 0};
    SimTK::Force::MobilityLinearDamper damper{scene.forces, scene.body, SimTK::MobilizerUIndex(0), kDamping};
    JointImpedanceJacobian jacobian{scene.matter, scene.forces,
                                    {system::JointImpedance{scene.body.getMobilizedBodyIndex(), kStiffness, kDamping, {}}}};

    static double calcExact(double t) {
        const double disc = std::sqrt(kDamping * kDamping - 4 * kMass * kStiffness);
        const double r1 = (-kDamping + disc) / (2 * kMass), r2 = (-kDamping - disc) / (2 * kMass);
        const double b = -r1 * kStart / (r2 - r1);  // x(0) = x0, x'(0) = 0
        return (kStart - b) * std::exp(r1 * t) + b * std::exp(r2 * t);
    }
    double runTo(double h, double duration, int order) {
        SimTK::State state = scene.system.realizeTopology();
        scene.body.setOneQ(state, 0, kStart);
        LinearlyImplicitOptions options;
        options.stepSize = h;
        options.order = order;
        LinearlyImplicitStepper stepper(scene.system, {&jacobian}, options);
        stepper.initialize(state);
        stepper.stepTo(duration);
        return scene.body.getOneQ(stepper.getState(), 0);
    }
};

// Error ratios when h halves: 2 for Euler (order 1), 4 for ROS2 (order 2).
void expectConvergenceOrder(int order) {
    const double T = 0.1;
    double previousError = 0;
    for (double h : {4e-3, 2e-3, 1e-3}) {  // 20x down to 5x the explicit limit
        StiffDamper damper;
        const double x = damper.runTo(h, T, order);
        const double error = std::abs(x - StiffDamper::calcExact(T));
        ::testing::Test::RecordProperty("order" + std::to_string(order) + "_error_um_at_h_us_" +
                                            std::to_string(static_cast<int>(h * 1e6)), std::to_string(error * 1e6));
        EXPECT_LT(error, 0.1 * StiffDamper::kStart);
        if (previousError > 0) {
            EXPECT_NEAR(previousError / error, order == 1 ? 2.0 : 4.0, order == 1 ? 0.15 : 0.5) << h;
        }
        previousError = error;
    }
}

TEST(LinearlyImplicitStepper, StiffDamperStableAndFirstOrderWithEuler) { expectConvergenceOrder(1); }
TEST(LinearlyImplicitStepper, StiffDamperStableAndSecondOrderWithRosenbrock) { expectConvergenceOrder(2); }

// A double pendulum of two 1 kg, 0.5 m links (two pins, a coupled 2x2 mass matrix), started at
// 1 and -0.5 rad, against Simbody's Runge-Kutta-Merson at 1e-10: the error-controlled ROS2 stays
// within 1e-3 rad over 1 s (measured 2e-5 at accuracy 1e-5) with steps its error chose.
TEST(LinearlyImplicitStepper, ErrorControlledDoublePendulumMatchesRungeKutta) {
    SimTK::MultibodySystem system;
    SimTK::SimbodyMatterSubsystem matter(system);
    SimTK::GeneralForceSubsystem forces(system);
    SimTK::Force::Gravity gravity(forces, matter, SimTK::Vec3(0, -kG, 0));
    const SimTK::Body::Rigid link(SimTK::MassProperties(1, SimTK::Vec3(0, -0.25, 0), SimTK::UnitInertia::cylinderAlongY(0.02, 0.25).shiftFromCentroid(SimTK::Vec3(0, -0.25, 0))));
    SimTK::MobilizedBody::Pin upper(matter.updGround(), SimTK::Transform(), link, SimTK::Transform());
    SimTK::MobilizedBody::Pin lower(upper, SimTK::Transform(SimTK::Vec3(0, -0.5, 0)), link, SimTK::Transform());
    SimTK::State state = system.realizeTopology();
    upper.setOneQ(state, 0, 1.0);
    lower.setOneQ(state, 0, -0.5);

    SimTK::RungeKuttaMersonIntegrator reference(system);
    reference.setAccuracy(1e-10);
    SimTK::TimeStepper referenceStepper(system, reference);
    referenceStepper.initialize(state);
    LinearlyImplicitOptions options;
    options.stepSize = 0.05;
    options.accuracy = 1e-5;
    LinearlyImplicitStepper stepper(system, {}, options);
    stepper.initialize(state);
    double worst = 0;
    for (int i = 1; i <= 20; ++i) {
        referenceStepper.stepTo(0.05 * i);
        stepper.stepTo(0.05 * i);
        for (int k = 0; k < 2; ++k) worst = std::max(worst, std::abs(stepper.getState().getQ()[k] - reference.getState().getQ()[k]));
    }
    RecordProperty("max_angle_error_rad", std::to_string(worst));
    RecordProperty("steps", std::to_string(stepper.getNumStepsTaken()));
    EXPECT_LT(worst, 1e-3);
    EXPECT_GT(stepper.getNumStepsTaken(), 20);  // the error, not the 50 ms cap, chose the steps
}

// With error control the step's matrix (M - g D - g^2 K and its LU) is kept across steps of
// nearly the same size and rebuilt at least every 10 ms: on the stiff damper over 0.3 s, once
// the steps have grown to the 2 ms cap, about one build per 5 steps, and the answer still within
// the accuracy's reach of the exact solution.
TEST(LinearlyImplicitStepper, ErrorControlledStepsKeepTheirMatrixForAWhile) {
    StiffDamper damper;
    SimTK::State state = damper.scene.system.realizeTopology();
    damper.scene.body.setOneQ(state, 0, StiffDamper::kStart);
    LinearlyImplicitOptions options;
    options.stepSize = 2e-3;
    options.accuracy = 1e-4;
    LinearlyImplicitStepper stepper(damper.scene.system, {&damper.jacobian}, options);
    stepper.initialize(state);
    const double T = 0.3;
    stepper.stepTo(T);
    const IntegrationStatistics stats = stepper.getStatistics();
    RecordProperty("steps", std::to_string(stats.steps));
    RecordProperty("matrix_builds", std::to_string(stats.linearSolverSetups));
    EXPECT_GE(stats.steps, static_cast<long>(T / options.stepSize));
    EXPECT_LT(stats.linearSolverSetups, stats.steps / 2);  // kept
    EXPECT_GE(stats.linearSolverSetups, static_cast<long>(T / 0.01));  // but no longer than 10 ms
    EXPECT_NEAR(damper.scene.body.getOneQ(stepper.getState(), 0), StiffDamper::calcExact(T), 1e-4 * StiffDamper::kStart);
}

// A term reported by one contributor while the damper's x is above a level, and by another below
// it: each loses or gains its term at the crossing, which the stepper localizes. Oracle: the
// same run with the two terms' identifiers made different; equal identifiers of two contributors
// must not hide the switch (they did when the active set was one list of plain identifiers).
class LevelTerm : public ForceJacobianContributor {
public:
    LevelTerm(const SimTK::MobilizedBody& body, double level, bool above, int id, bool withMargin = false)
        : body_(body), level_(level), above_(above), id_(id), withMargin_(withMargin) {}
    void addForceJacobians(const SimTK::State&, SimTK::Matrix&, SimTK::Matrix&) const override {}
    void appendActiveSet(const SimTK::State& state, std::vector<int>& active) const override {
        if (findTermMargin(state, id_) > 0 || (!withMargin_ && (body_.getOneQ(state, 0) > level_) == above_)) {
            active.push_back(id_);
        }
    }
    double findTermMargin(const SimTK::State& state, int) const override {
        const double x = body_.getOneQ(state, 0);
        return withMargin_ ? (above_ ? x - level_ : level_ - x) : SimTK::NaN;
    }

private:
    const SimTK::MobilizedBody& body_;
    double level_;
    bool above_;
    int id_;
    bool withMargin_;
};

// The damper from kStart over 0.3 s at accuracy 1e-4, with the level terms when the ids are given;
// `x` receives the end's position (m).
IntegrationStatistics runDamper(std::optional<std::pair<int, int>> ids, double& x, bool withMargins = false) {
    StiffDamper damper;
    const double level = 0.5 * StiffDamper::kStart;
    const LevelTerm above(damper.scene.body, level, true, ids ? ids->first : 0, withMargins);
    const LevelTerm below(damper.scene.body, level, false, ids ? ids->second : 0, withMargins);
    std::vector<const ForceJacobianContributor*> contributors{&damper.jacobian};
    if (ids) contributors.insert(contributors.end(), {&above, &below});
    SimTK::State state = damper.scene.system.realizeTopology();
    damper.scene.body.setOneQ(state, 0, StiffDamper::kStart);
    LinearlyImplicitOptions options;
    options.stepSize = 2e-3;
    options.accuracy = 1e-4;
    LinearlyImplicitStepper stepper(damper.scene.system, contributors, options);
    stepper.initialize(state);
    stepper.stepTo(0.3);
    x = damper.scene.body.getOneQ(stepper.getState(), 0);
    return stepper.getStatistics();
}

TEST(LinearlyImplicitStepper, EqualTermIdentifiersOfTwoContributorsStayTwoTerms) {
    double xApart = 0, xEqual = 0, xNone = 0;
    const IntegrationStatistics apart = runDamper(std::pair{1, 2}, xApart);
    const IntegrationStatistics equal = runDamper(std::pair{1, 1}, xEqual);
    const IntegrationStatistics none = runDamper(std::nullopt, xNone);
    EXPECT_GT(apart.errorTestFailures, none.errorTestFailures);  // the crossing was localized
    EXPECT_EQ(equal.steps, apart.steps);
    EXPECT_EQ(equal.errorTestFailures, apart.errorTestFailures);
    EXPECT_EQ(xEqual, xApart);
}

// The level's crossing localized from the terms' margins (x - level, linear enough over a step)
// instead of by bisection: fewer attempts, and the same run to within the accuracy. Oracle: the
// bisecting run and the closed form.
TEST(LinearlyImplicitStepper, MarginsLocalizeASwitchInFewerAttempts) {
    double xBisected = 0, xEstimated = 0;
    const IntegrationStatistics bisected = runDamper(std::pair{1, 2}, xBisected);
    const IntegrationStatistics estimated = runDamper(std::pair{1, 2}, xEstimated, true);
    RecordProperty("attempts_bisected", std::to_string(bisected.errorTestFailures));
    RecordProperty("attempts_estimated", std::to_string(estimated.errorTestFailures));
    EXPECT_LT(estimated.errorTestFailures, bisected.errorTestFailures);
    EXPECT_GE(estimated.errorTestFailures, 1);  // the crossing was still localized
    EXPECT_NEAR(xEstimated, StiffDamper::calcExact(0.3), 1e-4 * StiffDamper::kStart);
    EXPECT_NEAR(xBisected, StiffDamper::calcExact(0.3), 1e-4 * StiffDamper::kStart);
}

TEST(LinearlyImplicitStepper, ReportsLandOnTheirTimesBetweenSteps) {
    StiffDamper damper;
    SimTK::State state = damper.scene.system.realizeTopology();
    LinearlyImplicitOptions options;
    options.stepSize = 3e-3;
    options.order = 1;
    LinearlyImplicitStepper stepper(damper.scene.system, {&damper.jacobian}, options);
    stepper.initialize(state);
    stepper.stepTo(0.01);  // 4 equal steps of 2.5 ms
    EXPECT_DOUBLE_EQ(stepper.getState().getTime(), 0.01);
    EXPECT_EQ(stepper.getNumStepsTaken(), 4);
    EXPECT_EQ(stepper.getStatistics().rhsEvaluations, 5);  // one per step and one at initialize
}

// Dense output: under error control the steps go on past the times asked for and the state there
// is interpolated (cubic Hermite). Oracle: the analytic solution at every output time (0.7 ms
// apart, not on the step ends), and the steps of a run asked for one time only (outputs must
// not cut the steps). Landing on each output instead (interpolate = false) costs steps.
TEST(LinearlyImplicitStepper, ErrorControlledOutputsAreInterpolated) {
    const double T = 0.3, every = 0.7e-3;
    const auto run = [&](bool interpolate, double outputEvery, double& last) {
        StiffDamper damper;
        SimTK::State state = damper.scene.system.realizeTopology();
        damper.scene.body.setOneQ(state, 0, StiffDamper::kStart);
        LinearlyImplicitOptions options;
        options.stepSize = 2e-3;
        options.accuracy = 1e-4;
        options.interpolate = interpolate;
        LinearlyImplicitStepper stepper(damper.scene.system, {&damper.jacobian}, options);
        stepper.initialize(state);
        double worst = 0;
        for (double t = outputEvery; t < T; t += outputEvery) {
            stepper.stepTo(t);
            EXPECT_EQ(stepper.getState().getTime(), t);
            worst = std::max(worst, std::abs(damper.scene.body.getOneQ(stepper.getState(), 0) - StiffDamper::calcExact(t)));
        }
        stepper.stepTo(T);
        last = damper.scene.body.getOneQ(stepper.getState(), 0);
        // The step ends are controlled to 1e-4 (absolute on x, |x| << 1) and measured within 1e-6;
        // between them, the cubic across the fast 0.1 ms mode's decay is within 2e-6 (measured).
        EXPECT_LT(worst, 1e-3 * StiffDamper::kStart) << "interpolate " << interpolate;
        return stepper.getStatistics().steps;
    };
    double once = 0, sampled = 0, landed = 0;
    const long stepsOnce = run(true, T, once);
    const long stepsSampled = run(true, every, sampled), stepsLanded = run(false, every, landed);
    RecordProperty("steps_once_sampled_landed", std::to_string(stepsOnce) + " " + std::to_string(stepsSampled) + " " +
                                                    std::to_string(stepsLanded));
    // Outputs half a step or more ahead are landed on (cheaper than an interpolation): a few while
    // the steps are short, none once they have grown past twice the output interval.
    EXPECT_LE(stepsSampled, stepsOnce + stepsOnce / 10);
    EXPECT_GT(stepsLanded, stepsOnce + static_cast<long>(T / every) / 2);
    for (double x : {once, sampled, landed}) EXPECT_NEAR(x, StiffDamper::calcExact(T), 1e-4 * StiffDamper::kStart);
}

// A periodic check that changes nothing is served on interpolated states (the steps are those of a
// run without it); one that changes the state is landed on, every time.
class PeriodicCheck : public SimTK::PeriodicEventHandler {
public:
    PeriodicCheck(double interval, bool touch) : SimTK::PeriodicEventHandler(interval), touch_(touch) {}
    void handleEvent(SimTK::State& state, SimTK::Real, bool& terminate) const override {
        terminate = false;
        ++calls;
        if (touch_) state.updU() *= 1.0;  // same values, but Stage::Velocity invalidated: a change
    }
    mutable int calls = 0;

private:
    bool touch_;
};

long countControlledSteps(int check, int& calls) {  // check: 0 none, 1 changes nothing, 2 changes the state
    StiffDamper damper;
    auto* handler = check > 0 ? new PeriodicCheck(1e-3, check == 2) : nullptr;
    if (handler) damper.scene.system.addEventHandler(handler);  // the System owns it
    SimTK::State state = damper.scene.system.realizeTopology();
    damper.scene.body.setOneQ(state, 0, StiffDamper::kStart);
    LinearlyImplicitOptions options;
    options.stepSize = 2e-3;
    options.accuracy = 1e-4;
    LinearlyImplicitStepper stepper(damper.scene.system, {&damper.jacobian}, options);
    stepper.initialize(state);
    stepper.stepTo(0.3);
    calls = handler ? handler->calls : 0;
    return stepper.getStatistics().steps;
}

TEST(LinearlyImplicitStepper, ScheduledEventsLandOnlyWhenTheyChangeTheState) {
    int calls = 0;
    const long plain = countControlledSteps(0, calls);
    EXPECT_EQ(countControlledSteps(1, calls), plain);
    EXPECT_EQ(calls, 300);
    EXPECT_GE(countControlledSteps(2, calls), std::max(plain, 300L));
    EXPECT_EQ(calls, 300);
}

// A force F that jumps on at t_L (`t >= t_L`, as a perturbation's or a capacity load's start).
class StepForce : public SimTK::Force::Custom::Implementation {
public:
    StepForce(const SimTK::MobilizedBody& body, double start, double force) : body_(body), start_(start), force_(force) {}
    void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>&, SimTK::Vector_<SimTK::Vec3>&,
                   SimTK::Vector& mobilityForces) const override {
        if (s.getTime() >= start_) body_.applyOneMobilityForce(s, 0, force_, mobilityForces);
    }
    SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }

private:
    const SimTK::MobilizedBody& body_;
    double start_, force_;
};

// A body at rest, F jumping on at a landing time between the 5 ms steps. Oracle: x = F (t - t_L)^2
// / 2m from t_L, which ROS2 follows exactly (constant acceleration) if no step sees the jump early:
// the step that ends on t_L sees the force from the left there. Evaluated at t_L itself, the
// second stage put half the step's weight on F: the body left t_L at F h / 2m (0.31 mm/s after
// the 4.1 ms step there), 0.09 mm ahead at 0.3 s.
TEST(LinearlyImplicitStepper, AStepEndingOnALandingTimeSeesTheJumpAfterIt) {
    constexpr double kMass = 2, kForce = 0.3, kStart = 0.0123, T = 0.3;
    SliderScene scene(kMass, 0);
    SimTK::Force::Custom(scene.forces, new StepForce(scene.body, kStart, kForce));
    LinearlyImplicitOptions options;
    options.stepSize = 5e-3;
    options.accuracy = 1e-3;
    options.landingTimes = {kStart};
    LinearlyImplicitStepper stepper(scene.system, {}, options);
    stepper.initialize(scene.system.realizeTopology());
    stepper.stepTo(kStart);
    EXPECT_EQ(scene.body.getOneU(stepper.getState(), 0), 0);
    stepper.stepTo(T);
    const double dt = T - kStart;
    EXPECT_NEAR(scene.body.getOneU(stepper.getState(), 0), kForce / kMass * dt, 1e-12);
    EXPECT_NEAR(scene.body.getOneQ(stepper.getState(), 0), kForce / (2 * kMass) * dt * dt, 1e-12);
}

// A damper the stepper has no Jacobian of, m u' = -c u: ROS2 treats it explicitly. With
// lambda = -c/m and z = h lambda its stages reduce, in u, to Heun's method, u_k+1 = R(z) u_k with
// R(z) = 1 + z + z^2/2 (stable for -2 <= z <= 0), and its error estimate has a closed form from
// the same tableau (the Jacobian keeps only x' = u, so W^-1 = [[1, g], [0, 1]], g = gamma h):
//   f_u = u_k z^2 / 2,  f_x = h u_k (z (1 - 2 gamma) + 2 gamma z^2) / 2 + 0,
//   estimate = sqrt((f_x^2 + (f_u / (1 + |u_k|))^2) / 2)  (the state's own scale: accuracy 1).
struct ExplicitDamper {
    static constexpr double kMass = 1, kDamping = 1000;  // lambda = -1000 /s
    SliderScene scene{kMass, 0};
    SimTK::Force::MobilityLinearDamper damper{scene.forces, scene.body, SimTK::MobilizerUIndex(0), kDamping};

    static double calcEstimate(double h, double u) {
        const double z = -kDamping / kMass * h, gamma = 1 + 1 / std::sqrt(2.0);
        const double fu = u * z * z / 2, fx = h * u * (z * (1 - 2 * gamma) + 2 * gamma * z * z) / 2;
        return std::sqrt((fx * fx + std::pow(fu / (1 + std::abs(u)), 2)) / 2);
    }
    static double calcGrowth(double h) {
        const double z = -kDamping / kMass * h;
        return 1 + z + z * z / 2;
    }
    // Fixed steps of h from speed u0 up to `duration`; the speed there.
    double runTo(double h, double u0, double duration) {
        SimTK::State state = scene.system.realizeTopology();
        scene.body.setOneU(state, 0, u0);
        LinearlyImplicitOptions options;
        options.stepSize = h;
        LinearlyImplicitStepper stepper(scene.system, {}, options);
        stepper.initialize(state);
        stepper.stepTo(duration);
        return scene.body.getOneU(stepper.getState(), 0);
    }
};

// z = -1: R = 0.5, the run decays as the closed form says and no step's estimate (0.18 at most,
// at the start) comes near the state's scale: no throw. (The stiff dampers above, in the
// Jacobian, are the L-stable case: z down to -40 at fixed steps, no throw either.)
TEST(LinearlyImplicitStepper, FixedStepsOnAStableExplicitDamperRunThrough) {
    constexpr double h = 1e-3, u0 = 1;
    ASSERT_LT(ExplicitDamper::calcEstimate(h, u0), LinearlyImplicitStepper::kUntrustedStepEstimate);
    ExplicitDamper damper;
    EXPECT_NEAR(damper.runTo(h, u0, 10 * h), u0 * std::pow(ExplicitDamper::calcGrowth(h), 10), 1e-12);
}

// z = -3: R = 2.5, the speed grows 2.5x a step and so does the estimate with it; the run stops
// with FixedStepTooLongError at the first step whose closed-form estimate exceeds the state's
// scale (from 1 cm/s: the sixth, at 15 ms), naming that step's start, size and estimate.
TEST(LinearlyImplicitStepper, FixedStepsOnAnUnstableExplicitDamperStopAtTheFirstUntrustedStep) {
    constexpr double h = 3e-3, u0 = 0.01;
    int k = 0;
    double u = u0;
    while (ExplicitDamper::calcEstimate(h, u) <= LinearlyImplicitStepper::kUntrustedStepEstimate) {
        u *= ExplicitDamper::calcGrowth(h);
        ++k;
    }
    ASSERT_EQ(k, 5);
    ExplicitDamper damper;
    try {
        damper.runTo(h, u0, 30 * h);
        FAIL() << "an unstable fixed step ran through";
    } catch (const FixedStepTooLongError& e) {
        EXPECT_NEAR(e.getTime(), k * h, 1e-12);
        EXPECT_NEAR(e.getStepSize(), h, 1e-15);
        EXPECT_NEAR(e.getEstimate(), ExplicitDamper::calcEstimate(h, u), 1e-9 * e.getEstimate());
        EXPECT_NE(std::string(e.what()).find("fixed step 0.003 s"), std::string::npos) << e.what();
    }
}

TEST(LinearlyImplicitStepper, RejectsBadOptions) {
    SliderScene scene(0.1, kG);
    LinearlyImplicitOptions options;
    options.order = 3;
    EXPECT_THROW(LinearlyImplicitStepper(scene.system, {}, options), InputError);
    options.order = 1;
    options.accuracy = 1e-3;  // error control needs ROS2's estimate
    EXPECT_THROW(LinearlyImplicitStepper(scene.system, {}, options), InputError);
    options = {};
    options.landingTimes = {0.1, std::nan("")};
    EXPECT_THROW(LinearlyImplicitStepper(scene.system, {}, options), InputError);
}

TEST(LinearlyImplicitStepper, RejectsBadStepSize) {
    SliderScene scene(0.1, kG);
    for (double h : {0.0, -1e-3, std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()}) {
        LinearlyImplicitOptions options;
        options.stepSize = h;
        EXPECT_THROW(LinearlyImplicitStepper(scene.system, {}, options), InputError) << h;
    }
}

}  // namespace
}  // namespace graspsim::integration
