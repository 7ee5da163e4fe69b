// The fixed-step linearly implicit Euler stepper against closed forms: a free fall (the scheme's
// exact discrete solution, and first-order convergence to the continuous one), and a stiff
// overdamped spring-damper (stable at 10x the explicit limit, first-order convergence to the
// analytic solution). Bad options throw.

#include "graspsim/integration/linearly_implicit_stepper.h"

#include "graspsim/error.h"
#include "graspsim/integration/joint_impedance_jacobian.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

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

double fallTo(double h, double duration, double& discreteOracle) {
    SliderScene scene(0.1, kG);
    SimTK::State state = scene.system.realizeTopology();
    LinearlyImplicitOptions options;
    options.stepSize = h;
    LinearlyImplicitStepper stepper(scene.system, {}, options);
    stepper.initialize(state);
    stepper.stepTo(duration);
    const double n = std::round(duration / h);
    discreteOracle = -kG * h * h * n * (n + 1) / 2;  // u_k = -g k h, y_k = sum h u_j
    return scene.body.getOneQ(stepper.getState(), 0);
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
    double runTo(double h, double duration) {
        SimTK::State state = scene.system.realizeTopology();
        scene.body.setOneQ(state, 0, kStart);
        LinearlyImplicitOptions options;
        options.stepSize = h;
        LinearlyImplicitStepper stepper(scene.system, {&jacobian}, options);
        stepper.initialize(state);
        stepper.stepTo(duration);
        return scene.body.getOneQ(stepper.getState(), 0);
    }
};

TEST(LinearlyImplicitStepper, StiffDamperStableAndFirstOrder) {
    const double T = 0.1;
    double previousError = 0;
    for (double h : {4e-3, 2e-3, 1e-3}) {  // 20x down to 5x the explicit limit
        StiffDamper damper;
        const double x = damper.runTo(h, T);
        const double error = std::abs(x - StiffDamper::calcExact(T));
        RecordProperty("error_um_at_h_us_" + std::to_string(static_cast<int>(h * 1e6)), std::to_string(error * 1e6));
        EXPECT_LT(error, 0.1 * StiffDamper::kStart);
        if (previousError > 0) {
            EXPECT_NEAR(previousError / error, 2.0, 0.15);
        }
        previousError = error;
    }
}

TEST(LinearlyImplicitStepper, ReportsLandOnTheirTimesBetweenSteps) {
    StiffDamper damper;
    SimTK::State state = damper.scene.system.realizeTopology();
    LinearlyImplicitOptions options;
    options.stepSize = 3e-3;
    LinearlyImplicitStepper stepper(damper.scene.system, {&damper.jacobian}, options);
    stepper.initialize(state);
    stepper.stepTo(0.01);  // 4 equal steps of 2.5 ms
    EXPECT_DOUBLE_EQ(stepper.getState().getTime(), 0.01);
    EXPECT_EQ(stepper.getNumStepsTaken(), 4);
    EXPECT_EQ(stepper.getStatistics().rhsEvaluations, 5);  // one per step and one at initialize
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
