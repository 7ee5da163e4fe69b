// LimitedBushing in a reduced scene with closed-form oracles: a box O on a Free mobilizer,
// bushed to Ground (H = Ground), gravity off, a constant force or torque on it. Below the limit
// the element holds it (static deflection F/K); above, O slides with (|F| - L) / m or
// (|T| - L) / I. Each dynamic case runs with an explicit (Runge-Kutta-Merson) and an implicit
// (CPodes BDF) integrator.
#include "graspsim/grasp/limited_bushing.h"

#include <gtest/gtest.h>

#include "stepped_run.h"

#include <cmath>
#include <memory>
#include <string>

#include "graspsim/error.h"

namespace graspsim::grasp {
namespace {

using SimTK::Vec3;
using SimTK::Vec6;
using test::calcAngleAboutZ;
using test::IntegratorKind;
using test::SteppedRun;

constexpr double kMass = 0.5;                     // kg
constexpr double kInertia = 0.01;                 // kg m^2, about every axis through the centre
constexpr double kLinearStiffness = 1e4;          // N/m
constexpr double kAngularStiffness = 100;         // N m/rad
constexpr double kLinearLimit = 2;                // N
constexpr double kAngularLimit = 0.1;             // N m
// Critical damping 2 sqrt(K m): the step load never overshoots its static deflection.
const double kLinearDamping = 2 * std::sqrt(kLinearStiffness * kMass);
const double kAngularDamping = 2 * std::sqrt(kAngularStiffness * kInertia);

// The scene: O's centre at the Ground origin, M = O's frame, F = Ground's frame.
struct BushedBox {
    SimTK::MultibodySystem system;
    SimTK::SimbodyMatterSubsystem matter{system};
    SimTK::GeneralForceSubsystem forces{system};
    SimTK::MobilizedBody::Free box;
    LimitedBushing bushing;

    BushedBox() {
        const SimTK::Body::Rigid body(SimTK::MassProperties(
            kMass, Vec3(0), SimTK::UnitInertia(kInertia / kMass)));
        box = SimTK::MobilizedBody::Free(matter.Ground(), body);
        const Vec6 stiffness(kAngularStiffness, kAngularStiffness, kAngularStiffness,
                             kLinearStiffness, kLinearStiffness, kLinearStiffness);
        const Vec6 damping(kAngularDamping, kAngularDamping, kAngularDamping, kLinearDamping,
                           kLinearDamping, kLinearDamping);
        bushing = LimitedBushing(forces, matter.Ground(), SimTK::Transform(), box,
                                 SimTK::Transform(), stiffness, damping);
    }
    void addForce(const Vec3& F_G) { SimTK::Force::ConstantForce(forces, box, Vec3(0), F_G); }
    void addTorque(const Vec3& T_G) { SimTK::Force::ConstantTorque(forces, box, T_G); }

    // Initial state: O at rest at the origin, anchor there, `axis` relaxed to `limit`.
    SimTK::State makeState(BushingAxis axis, double limit) {
        SimTK::State state = system.realizeTopology();
        system.realize(state, SimTK::Stage::Position);
        bushing.resetAnchor(state);
        Vec6 limits(SimTK::Infinity);
        limits[toIndex(axis)] = limit;
        bushing.setLimits(state, limits);
        bushing.setAxisLocked(state, axis, false);
        return state;
    }
};

class LimitedBushingDynamics : public testing::TestWithParam<IntegratorKind> {};

TEST_P(LimitedBushingDynamics, HoldsAForceBelowTheLimit) {
    BushedBox scene;
    const double force = 0.75 * kLinearLimit;
    scene.addForce(Vec3(force, 0, 0));
    SteppedRun run(GetParam(), scene.system, scene.makeState(BushingAxis::TranslationX, kLinearLimit));
    const SimTK::State& state = run.stepTo(0.2);  // 28 time constants sqrt(m/K) = 7 ms
    const Vec3 p = scene.box.getBodyOriginLocation(state);
    EXPECT_NEAR(p[0], force / kLinearStiffness, 1e-3 * force / kLinearStiffness);
    EXPECT_LT((p - Vec3(p[0], 0, 0)).norm(), 1e-12);
    EXPECT_LT(scene.box.getBodyVelocity(state).norm(), 1e-6);
    EXPECT_FALSE(scene.bushing.isSliding(state, BushingAxis::TranslationX));
    EXPECT_NEAR(scene.bushing.findWrench(state)[1][0], -force, 1e-3 * force);
}

TEST_P(LimitedBushingDynamics, SlidesWithTheExcessForceAboveTheLimit) {
    BushedBox scene;
    const double force = 2.5 * kLinearLimit;
    scene.addForce(Vec3(force, 0, 0));
    SteppedRun run(GetParam(), scene.system, scene.makeState(BushingAxis::TranslationX, kLinearLimit));
    const double t1 = 0.1, t2 = 0.3;
    const double v1 = scene.box.getBodyVelocity(run.stepTo(t1))[1][0];
    const SimTK::State& state = run.stepTo(t2);
    const double v2 = scene.box.getBodyVelocity(state)[1][0];
    const double expected = (force - kLinearLimit) / kMass;
    EXPECT_NEAR((v2 - v1) / (t2 - t1), expected, 0.02 * expected);
    EXPECT_TRUE(scene.bushing.isSliding(state, BushingAxis::TranslationX));
    EXPECT_NEAR(scene.bushing.findWrench(state)[1][0], -kLinearLimit, 0.02 * kLinearLimit);
    // The anchor followed O: its elastic displacement stays at the limit's deflection L/K.
    EXPECT_NEAR(scene.bushing.findDisplacement(state)[toIndex(BushingAxis::TranslationX)],
                kLinearLimit / kLinearStiffness, 0.02 * kLinearLimit / kLinearStiffness);
}

TEST_P(LimitedBushingDynamics, HoldsATorqueBelowTheLimit) {
    BushedBox scene;
    const double torque = 0.5 * kAngularLimit;
    scene.addTorque(Vec3(0, 0, torque));
    SteppedRun run(GetParam(), scene.system, scene.makeState(BushingAxis::RotationZ, kAngularLimit));
    const SimTK::State& state = run.stepTo(0.2);  // 20 time constants sqrt(I/K) = 10 ms
    const double angle = calcAngleAboutZ(scene.box.getBodyRotation(state));
    EXPECT_NEAR(angle, torque / kAngularStiffness, 1e-3 * torque / kAngularStiffness);
    EXPECT_LT(scene.box.getBodyVelocity(state).norm(), 1e-6);
    EXPECT_FALSE(scene.bushing.isSliding(state, BushingAxis::RotationZ));
}

TEST_P(LimitedBushingDynamics, SpinsWithTheExcessTorqueAboveTheLimit) {
    BushedBox scene;
    const double torque = 3 * kAngularLimit;
    scene.addTorque(Vec3(0, 0, torque));
    SteppedRun run(GetParam(), scene.system, scene.makeState(BushingAxis::RotationZ, kAngularLimit));
    // Spins about 2.5 rad by t2, well past small angles: exercises the anchor's rotation chart.
    const double t1 = 0.2, t2 = 0.5;
    const double w1 = scene.box.getBodyVelocity(run.stepTo(t1))[0][2];
    const SimTK::State& state = run.stepTo(t2);
    const double w2 = scene.box.getBodyVelocity(state)[0][2];
    const double expected = (torque - kAngularLimit) / kInertia;
    EXPECT_NEAR((w2 - w1) / (t2 - t1), expected, 0.02 * expected);
    EXPECT_TRUE(scene.bushing.isSliding(state, BushingAxis::RotationZ));
    const SimTK::SpatialVec wrench = scene.bushing.findWrench(state);
    EXPECT_NEAR(wrench[0][2], -kAngularLimit, 0.02 * kAngularLimit);
    EXPECT_LT(wrench[1].norm(), 1e-6);  // locked translation stays unloaded
}

// Two-sided limits on translation x, L- = 1 N and L+ = 3 N: a pull F along +x needs the force -F
// on O, bounded by L-, so 2 N slides with (2 - 1) / m; a push -2 N is held (deflection -2 N / K);
// -4 N slides with (4 - 3) / m.
TEST_P(LimitedBushingDynamics, TwoSidedLimitsHoldAndSlideOnEachSide) {
    const double lower = 1, upper = 3;
    for (double force : {2.0, -2.0, -4.0}) {
        BushedBox scene;
        scene.addForce(Vec3(force, 0, 0));
        SimTK::State start = scene.makeState(BushingAxis::TranslationX, kLinearLimit);
        Vec6 lowers(SimTK::Infinity), uppers(SimTK::Infinity);
        lowers[3] = lower;
        uppers[3] = upper;
        scene.bushing.setLimits(start, lowers, uppers);
        EXPECT_EQ(scene.bushing.getLowerLimits(start)[3], lower);
        EXPECT_EQ(scene.bushing.findEffectiveLimits(start)[3], upper);
        SteppedRun run(GetParam(), scene.system, start);
        const double t1 = 0.1, t2 = 0.3;
        const double v1 = scene.box.getBodyVelocity(run.stepTo(t1))[1][0];
        const SimTK::State& state = run.stepTo(t2);
        const double v2 = scene.box.getBodyVelocity(state)[1][0];
        const double side = force > 0 ? lower : upper;
        if (std::abs(force) < side) {
            EXPECT_NEAR(scene.box.getBodyOriginLocation(state)[0], force / kLinearStiffness, 1e-3 * std::abs(force) / kLinearStiffness);
            EXPECT_FALSE(scene.bushing.isSliding(state, BushingAxis::TranslationX));
            EXPECT_NEAR(scene.bushing.findWrench(state)[1][0], -force, 1e-3 * std::abs(force));
        } else {
            const double expected = (force - std::copysign(side, force)) / kMass;
            EXPECT_NEAR((v2 - v1) / (t2 - t1), expected, 0.02 * std::abs(expected)) << "force " << force;
            EXPECT_TRUE(scene.bushing.isSliding(state, BushingAxis::TranslationX));
            EXPECT_NEAR(scene.bushing.findWrench(state)[1][0], -std::copysign(side, force), 0.02 * side);
        }
    }
}

// A coupled stiffness (rotation z and translation x sharing c = 50 N/rad on the diagonal's
// 100 N m/rad and 1e4 N/m): a force F along x below the limit is held where K e = (0, 0, 0, F, 0, 0),
// so the box also turns about z, by theta = -c F / det and x = K_r F / det, det = K_r K_t - c^2
// (closed form; small angles). Beyond the limit (K e)_x reaches L and the box slides with
// (F - L) / m, as without coupling (Newton).
TEST_P(LimitedBushingDynamics, CoupledStiffnessHoldsAtTheClosedFormAndSlidesAtTheLimit) {
    const double c = 50;
    SimTK::Mat66 K;
    for (int r = 0; r < 6; ++r) {
        for (int col = 0; col < 6; ++col) K(r, col) = r == col ? (r < 3 ? kAngularStiffness : kLinearStiffness) : 0.0;
    }
    K(2, 3) = K(3, 2) = c;
    for (double force : {0.75 * kLinearLimit, 2.5 * kLinearLimit}) {
        BushedBox scene;
        scene.addForce(Vec3(force, 0, 0));
        SimTK::State start = scene.makeState(BushingAxis::TranslationX, kLinearLimit);
        scene.bushing.setStiffness(start, K, scene.bushing.getDamping());
        SteppedRun run(GetParam(), scene.system, start);
        const double t1 = 0.1, t2 = 0.3;
        const double v1 = scene.box.getBodyVelocity(run.stepTo(t1))[1][0];
        const SimTK::State& state = run.stepTo(t2);
        if (force < kLinearLimit) {
            const double det = kAngularStiffness * kLinearStiffness - c * c;
            const double x = kAngularStiffness * force / det, theta = -c * force / det;
            EXPECT_NEAR(scene.box.getBodyOriginLocation(state)[0], x, 1e-3 * x);
            EXPECT_NEAR(calcAngleAboutZ(scene.box.getBodyRotation(state)), theta, 1e-3 * std::abs(theta));
            EXPECT_GT(std::abs(theta), 1e-5);  // the coupling turned it
            EXPECT_FALSE(scene.bushing.isSliding(state, BushingAxis::TranslationX));
        } else {
            const double v2 = scene.box.getBodyVelocity(state)[1][0];
            const double expected = (force - kLinearLimit) / kMass;
            EXPECT_NEAR((v2 - v1) / (t2 - t1), expected, 0.02 * expected);
            EXPECT_TRUE(scene.bushing.isSliding(state, BushingAxis::TranslationX));
            EXPECT_NEAR(scene.bushing.findWrench(state)[1][0], -kLinearLimit, 0.02 * kLinearLimit);
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Integrators, LimitedBushingDynamics,
                         testing::Values(IntegratorKind::RungeKuttaMerson, IntegratorKind::CPodes),
                         [](const testing::TestParamInfo<IntegratorKind>& paramInfo) {
                             return std::string(paramInfo.param == IntegratorKind::CPodes
                                                    ? "CPodes"
                                                    : "RungeKuttaMerson");
                         });

// ---- statics and state handling ------------------------------------------------------------

// O displaced and turned, then the anchor reset there: no spring force (no jump on engagement);
// with O moving, only the damping force D r remains.
TEST(LimitedBushing, ResetAnchorLeavesNoSpringForce) {
    BushedBox scene;
    SimTK::State state = scene.makeState(BushingAxis::TranslationX, kLinearLimit);
    scene.box.setQToFitTransform(
        state, SimTK::Transform(SimTK::Rotation(0.8, SimTK::UnitVec3(1, 2, 3)), Vec3(0.1, -0.2, 0.3)));
    scene.system.realize(state, SimTK::Stage::Velocity);
    EXPECT_GT(scene.bushing.findWrench(state).norm(), 1.0);  // stretched before the reset
    scene.bushing.resetAnchor(state);
    scene.system.realize(state, SimTK::Stage::Velocity);
    EXPECT_LT(scene.bushing.findDisplacement(state).norm(), 1e-12);
    EXPECT_LT(scene.bushing.findWrench(state).norm(), 1e-9);

    const double speed = 1e-4;  // m/s along y: damping force D v, below the (locked) limit
    scene.box.setUToFitLinearVelocity(state, Vec3(0, speed, 0));
    scene.system.realize(state, SimTK::Stage::Velocity);
    EXPECT_NEAR(scene.bushing.findWrench(state)[1][1], -kLinearDamping * speed, 1e-9);
}

TEST(LimitedBushing, SetAnchorDisplacementIsReadBack) {
    BushedBox scene;
    SimTK::State state = scene.makeState(BushingAxis::TranslationX, kLinearLimit);
    const Vec6 e(1e-3, -2e-3, 5e-4, 1e-5, -3e-5, 2e-5);
    scene.bushing.setAnchorDisplacement(state, e);
    scene.system.realize(state, SimTK::Stage::Velocity);
    EXPECT_LT((scene.bushing.findDisplacement(state) - e).norm(), 1e-12);
    // Locked axes carry -K e; relaxed x translation (K e = 0.1 N < L) too.
    const Vec6 f = scene.bushing.findGeneralizedForce(state);
    EXPECT_NEAR(f[toIndex(BushingAxis::RotationY)], -kAngularStiffness * e[1], 1e-9);
    EXPECT_NEAR(f[toIndex(BushingAxis::TranslationX)], -kLinearStiffness * e[3], 1e-9);
}

TEST(LimitedBushing, DisabledElementAppliesNothing) {
    BushedBox scene;
    const double force = 1.0;
    scene.addForce(Vec3(force, 0, 0));
    SimTK::State state = scene.makeState(BushingAxis::TranslationX, kLinearLimit);
    scene.bushing.setAnchorDisplacement(state, Vec6(0, 0, 0, 1e-4, 0, 0));
    scene.bushing.setEnabled(state, false);
    scene.box.setUToFitLinearVelocity(state, Vec3(0.5, 0, 0));
    scene.system.realize(state, SimTK::Stage::Acceleration);
    EXPECT_FALSE(scene.bushing.isEnabled(state));
    EXPECT_EQ(scene.bushing.findWrench(state).norm(), 0);
    EXPECT_NEAR(scene.box.getBodyAcceleration(state)[1][0], force / kMass, 1e-12);
    EXPECT_EQ(state.getZDot().norm(), 0);  // the anchor is frozen
    EXPECT_FALSE(scene.bushing.isSliding(state, BushingAxis::TranslationX));
}

// A lowered limit turns the excess elastic strain into slip at once (elasto-plastic).
TEST(LimitedBushing, LoweringALimitMovesTheAnchorToTheLimit) {
    BushedBox scene;
    SimTK::State state = scene.makeState(BushingAxis::TranslationX, SimTK::Infinity);
    scene.bushing.setAnchorDisplacement(state, Vec6(0, 0, 0, -5e-4, 0, 0));  // 5 N
    scene.system.realize(state, SimTK::Stage::Position);
    scene.bushing.setLimits(state, Vec6(SimTK::Infinity, SimTK::Infinity, SimTK::Infinity,
                                        kLinearLimit, SimTK::Infinity, SimTK::Infinity));
    scene.system.realize(state, SimTK::Stage::Velocity);
    EXPECT_NEAR(scene.bushing.findDisplacement(state)[3], -kLinearLimit / kLinearStiffness, 1e-12);
    EXPECT_NEAR(scene.bushing.findWrench(state)[1][0], kLinearLimit, 1e-9);
    // Locking the axis again leaves the anchor (limits only ever shrink the displacement).
    scene.bushing.setAxisLocked(state, BushingAxis::TranslationX, true);
    EXPECT_EQ(scene.bushing.findEffectiveLimits(state)[3], SimTK::Infinity);
}

// A two-sided limit moves the anchor to the limit of the side the displacement loads: e = +5e-4
// (force -5 N) goes to L- = 1 N, e = -5e-4 to L+ = 3 N.
TEST(LimitedBushing, TwoSidedLimitMovesTheAnchorToTheLoadedSidesLimit) {
    for (double e : {5e-4, -5e-4}) {
        BushedBox scene;
        SimTK::State state = scene.makeState(BushingAxis::TranslationX, SimTK::Infinity);
        scene.bushing.setAnchorDisplacement(state, Vec6(0, 0, 0, e, 0, 0));
        scene.system.realize(state, SimTK::Stage::Position);
        Vec6 lower(SimTK::Infinity), upper(SimTK::Infinity);
        lower[3] = 1;
        upper[3] = 3;
        scene.bushing.setLimits(state, lower, upper);
        scene.system.realize(state, SimTK::Stage::Velocity);
        const double side = e > 0 ? lower[3] : upper[3];
        EXPECT_NEAR(scene.bushing.findDisplacement(state)[3], std::copysign(side, e) / kLinearStiffness, 1e-12);
        EXPECT_NEAR(scene.bushing.findWrench(state)[1][0], -std::copysign(side, e), 1e-9);
    }
}

TEST(LimitedBushing, RejectsBadParametersNamingTheAxis) {
    BushedBox scene;
    Vec6 stiffness(1), damping(0);
    stiffness[4] = -3;
    try {
        LimitedBushing(scene.forces, scene.matter.Ground(), SimTK::Transform(), scene.box,
                       SimTK::Transform(), stiffness, damping);
        FAIL() << "negative stiffness accepted";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("stiffness on translation y is -3"),
                  std::string::npos)
            << error.what();
    }
    SimTK::State state = scene.makeState(BushingAxis::TranslationX, kLinearLimit);
    EXPECT_THROW(scene.bushing.setLimits(state, Vec6(1, 1, SimTK::NaN, 1, 1, 1)), InputError);
    EXPECT_THROW(scene.bushing.setSlipOnsetWidth(0), InputError);
}

// ---- stiffness per state (the grasp switch stiffens the element at engagement) ------------

// K and D set in the state, 10 times K and critically damped again: the new values rule the law.
void stiffenTenfold(const BushedBox& scene, SimTK::State& state, double& linearStiffness) {
    const double factor = 10;
    linearStiffness = factor * kLinearStiffness;
    const double angular = factor * kAngularStiffness;
    const double linearDamping = 2 * std::sqrt(linearStiffness * kMass);
    const double angularDamping = 2 * std::sqrt(angular * kInertia);
    scene.bushing.setStiffness(state, Vec6(angular, angular, angular, linearStiffness, linearStiffness, linearStiffness),
                               Vec6(angularDamping, angularDamping, angularDamping, linearDamping, linearDamping,
                                    linearDamping));
}

TEST_P(LimitedBushingDynamics, StiffnessSetInTheStateGivesTheStaticDeflection) {
    BushedBox scene;
    const double force = 0.75 * kLinearLimit;
    scene.addForce(Vec3(force, 0, 0));
    SimTK::State initial = scene.makeState(BushingAxis::TranslationX, kLinearLimit);
    double stiffness = 0;
    stiffenTenfold(scene, initial, stiffness);
    SteppedRun run(GetParam(), scene.system, initial);
    const SimTK::State& state = run.stepTo(0.2);  // 89 time constants sqrt(m/K)
    EXPECT_NEAR(scene.box.getBodyOriginLocation(state)[0], force / stiffness, 1e-3 * force / stiffness);
    EXPECT_EQ(scene.bushing.getStiffness(state)[3], stiffness);
    EXPECT_EQ(scene.bushing.getStiffness()[3], kLinearStiffness);  // the default is unchanged
}

TEST_P(LimitedBushingDynamics, StiffnessSetInTheStateGivesTheDeflectionAtTheLimit) {
    BushedBox scene;
    const double force = 2.5 * kLinearLimit;
    scene.addForce(Vec3(force, 0, 0));
    SimTK::State initial = scene.makeState(BushingAxis::TranslationX, kLinearLimit);
    double stiffness = 0;
    stiffenTenfold(scene, initial, stiffness);
    SteppedRun run(GetParam(), scene.system, initial);
    const SimTK::State& state = run.stepTo(0.3);
    EXPECT_TRUE(scene.bushing.isSliding(state, BushingAxis::TranslationX));
    EXPECT_NEAR(scene.bushing.findDisplacement(state)[toIndex(BushingAxis::TranslationX)], kLinearLimit / stiffness,
                0.02 * kLinearLimit / stiffness);
}

TEST(LimitedBushing, StiffnessInTheStateStartsAtTheDefaultAndIsChecked) {
    BushedBox scene;
    SimTK::State state = scene.makeState(BushingAxis::TranslationX, kLinearLimit);
    EXPECT_EQ(scene.bushing.getStiffness(state), scene.bushing.getStiffness());
    EXPECT_EQ(scene.bushing.getDamping(state), scene.bushing.getDamping());
    Vec6 stiffness(1), damping(0);
    stiffness[2] = 0;
    try {
        scene.bushing.setStiffness(state, stiffness, damping);
        FAIL() << "zero stiffness accepted";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("stiffness on rotation z is 0"), std::string::npos) << error.what();
    }
    EXPECT_THROW(scene.bushing.setStiffness(state, Vec6(1), Vec6(1, 1, 1, 1, -1, 1)), InputError);
}

// A coupled stiffness must be symmetric and positive definite; its diagonal is what getStiffness
// reports, and a per-axis setStiffness uncouples again.
TEST(LimitedBushing, CoupledStiffnessIsCheckedAndReadBack) {
    BushedBox scene;
    SimTK::State state = scene.makeState(BushingAxis::TranslationX, kLinearLimit);
    SimTK::Mat66 K;
    for (int r = 0; r < 6; ++r) {
        for (int c = 0; c < 6; ++c) K(r, c) = r == c ? 10.0 : 0.0;
    }
    K(0, 3) = K(3, 0) = 3;
    scene.bushing.setStiffness(state, K, Vec6(1));
    EXPECT_EQ(scene.bushing.findStiffnessMatrix(state)(3, 0), 3);
    EXPECT_EQ(scene.bushing.getStiffness(state), Vec6(10));
    SimTK::Mat66 asymmetric = K;
    asymmetric(0, 3) = 4;
    try {
        scene.bushing.setStiffness(state, asymmetric, Vec6(1));
        FAIL() << "an asymmetric matrix accepted";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("entry (0, 3) is 4"), std::string::npos) << error.what();
    }
    SimTK::Mat66 indefinite = K;
    indefinite(0, 3) = indefinite(3, 0) = 11;  // 11^2 > 10 x 10
    EXPECT_THROW(scene.bushing.setStiffness(state, indefinite, Vec6(1)), InputError);
    scene.bushing.setStiffness(state, Vec6(5), Vec6(1));
    EXPECT_EQ(scene.bushing.findStiffnessMatrix(state)(3, 0), 0);
    EXPECT_EQ(scene.bushing.findStiffnessMatrix(state)(3, 3), 5);
}

// ---- the grasp switch's usage: limits set from an event handler ---------------------------

// At its time, engages the friction limit on x as a grasp event handler would.
class LimitSwitch : public SimTK::ScheduledEventHandler {
public:
    LimitSwitch(const LimitedBushing& bushing, double time) : bushing_(bushing), time_(time) {}
    SimTK::Real getNextEventTime(const SimTK::State&, bool) const override { return time_; }
    void handleEvent(SimTK::State& state, SimTK::Real, bool&) const override {
        bushing_.setLimits(state, Vec6(SimTK::Infinity, SimTK::Infinity, SimTK::Infinity,
                                       kLinearLimit, SimTK::Infinity, SimTK::Infinity));
    }

private:
    LimitedBushing bushing_;
    double time_;
};

TEST_P(LimitedBushingDynamics, LimitSetByAnEventHandlerStartsTheSlide) {
    BushedBox scene;
    const double force = 2.5 * kLinearLimit, switchTime = 0.15;  // 21 sqrt(m/K)
    scene.addForce(Vec3(force, 0, 0));
    scene.system.addEventHandler(new LimitSwitch(scene.bushing, switchTime));
    SteppedRun run(GetParam(), scene.system,
            scene.makeState(BushingAxis::TranslationX, SimTK::Infinity));
    EXPECT_NEAR(scene.box.getBodyOriginLocation(run.stepTo(switchTime - 1e-3))[0],
                force / kLinearStiffness, 1e-3 * force / kLinearStiffness);  // held while locked
    const double t1 = 0.25, t2 = 0.45;
    const double v1 = scene.box.getBodyVelocity(run.stepTo(t1))[1][0];
    const double v2 = scene.box.getBodyVelocity(run.stepTo(t2))[1][0];
    const double expected = (force - kLinearLimit) / kMass;
    EXPECT_NEAR((v2 - v1) / (t2 - t1), expected, 0.02 * expected);
}

// ---- engagement with a preload and a stiffness of its own -----------------------------------

// Engaged (as the grasp switch does) under a constant force and torque, with a preload that is
// part of them and a soft rotational stiffness K_z of its own: the spring starts out carrying the
// preload, so O moves only by the rest, (F - P_F) / K_x and (T - P_T) / K_z; the preload's part
// causes no sag.
TEST_P(LimitedBushingDynamics, EngagedWithAPreloadMovesOnlyByTheLoadBeyondIt) {
    BushedBox scene;
    const double force = 1.5, torque = 0.06, preloadForce = 1.2, preloadTorque = 0.05, softStiffness = 3;
    scene.addForce(Vec3(force, 0, 0));
    scene.addTorque(Vec3(0, 0, torque));
    SimTK::State initial = scene.system.realizeTopology();
    scene.system.realize(initial, SimTK::Stage::Position);
    AttachmentEngagement engagement;
    engagement.limits = Vec6(kAngularLimit, kAngularLimit, kAngularLimit, kLinearLimit, kLinearLimit, kLinearLimit);
    engagement.leverArm = 0.01;
    engagement.penetrationBound = 1;  // the constructor's stiffness rules
    engagement.stiffness = Vec6(SimTK::NaN, SimTK::NaN, softStiffness, SimTK::NaN, SimTK::NaN, SimTK::NaN);
    engagement.preload = Vec6(0, 0, -preloadTorque, -preloadForce, 0, 0);  // on O, against the loads
    scene.bushing.engage(initial, engagement);
    EXPECT_EQ(scene.bushing.getStiffness(initial), Vec6(kAngularStiffness, kAngularStiffness, softStiffness,
                                                         kLinearStiffness, kLinearStiffness, kLinearStiffness));
    SteppedRun run(GetParam(), scene.system, initial);
    const SimTK::State& state = run.stepTo(1.0);  // 11 time constants sqrt(I / K_z)
    const double x = (force - preloadForce) / kLinearStiffness, angle = (torque - preloadTorque) / softStiffness;
    EXPECT_NEAR(scene.box.getBodyOriginLocation(state)[0], x, 1e-3 * x);
    EXPECT_NEAR(calcAngleAboutZ(scene.box.getBodyRotation(state)), angle, 1e-3 * angle);
}

}  // namespace
}  // namespace graspsim::grasp
