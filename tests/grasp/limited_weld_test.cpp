// LimitedWeld in reduced scenes with closed-form oracles: a box O on a Free mobilizer welded to
// Ground (H = Ground), gravity off, a force or torque on it. Below the limit the weld holds it
// still (reaction = -load); above, O slides with (|F| - L) / m or spins with (|T| - L) / I and
// the reaction is exactly the limit; once the load is gone, friction L stops it at the distance
// of uniform deceleration and it sticks there. Each dynamic case runs with an explicit
// (Runge-Kutta-Merson) and an implicit (CPodes BDF Newton, as the grasp runs use) integrator.
#include "graspsim/grasp/limited_weld.h"

#include <gtest/gtest.h>

#include "stepped_run.h"

#include <cmath>
#include <memory>
#include <string>
#include <tuple>

#include "graspsim/error.h"

namespace graspsim::grasp {
namespace {

using SimTK::Vec3;
using SimTK::Vec6;
using test::calcAngleAboutZ;
using test::IntegratorKind;
using test::SteppedRun;

constexpr double kMass = 0.5;          // kg
constexpr double kInertia = 0.01;      // kg m^2, about every axis through the centre
constexpr double kLinearLimit = 2;     // N
constexpr double kAngularLimit = 0.1;  // N m
// Drift allowed while held: the velocity constraint is kept to the integrator's tolerance only.
constexpr double kHeldDrift = 1e-6;  // m or rad

// A spatial load on O's centre (torque, force; in Ground) that switches off at `offTime`.
class StepLoad : public SimTK::Force::Custom::Implementation {
public:
    StepLoad(const SimTK::MobilizedBody& body, const SimTK::SpatialVec& load, double offTime)
        : body_(body), load_(load), offTime_(offTime) {}
    void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                   SimTK::Vector_<Vec3>&, SimTK::Vector&) const override {
        if (s.getTime() < offTime_) bodyForces[body_.getMobilizedBodyIndex()] += load_;
    }
    SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }

private:
    SimTK::MobilizedBody body_;
    SimTK::SpatialVec load_;
    double offTime_;
};

// The scene: O's centre at the Ground origin, M = O's frame, F = H's frame at the Ground origin.
// `lockable`: H is Ground, O's parent, so an all-stuck weld is O's mobilizer lock; otherwise H is
// a base welded to Ground at the origin, not O's parent, and the weld uses its constraints only.
struct WeldedBox {
    explicit WeldedBox(bool lockable = false)
        : weld(system, matter, forces, lockable ? SimTK::MobilizedBody(matter.Ground()) : SimTK::MobilizedBody(base),
               SimTK::Transform(), box, SimTK::Transform()) {}

    SimTK::MultibodySystem system;
    SimTK::SimbodyMatterSubsystem matter{system};
    SimTK::GeneralForceSubsystem forces{system};
    SimTK::MobilizedBody::Weld base{matter.Ground(), SimTK::Body::Rigid(SimTK::MassProperties(1, Vec3(0), SimTK::UnitInertia(1)))};
    SimTK::MobilizedBody::Free box{matter.Ground(), SimTK::Body::Rigid(SimTK::MassProperties(
                                                        kMass, Vec3(0), SimTK::UnitInertia(kInertia / kMass)))};
    LimitedWeld weld;

    void addLoad(const Vec3& torque, const Vec3& force, double offTime = SimTK::Infinity) {
        SimTK::Force::Custom(forces, new StepLoad(box, SimTK::SpatialVec(torque, force), offTime));
    }

    // O at rest at the origin, weld enabled with `limits`, axes with a finite limit relaxed.
    SimTK::State makeState(const Vec6& limits) {
        SimTK::State state = system.realizeTopology();
        system.realize(state, SimTK::Stage::Position);
        weld.setLimits(state, limits);
        for (int k = 0; k < 6; ++k) weld.setAxisLocked(state, static_cast<WeldAxis>(k), !std::isfinite(limits[k]));
        weld.setEnabled(state, true);
        return state;
    }
};

Vec6 limitOn(WeldAxis axis, double limit) {
    Vec6 limits(SimTK::Infinity);
    limits[toIndex(axis)] = limit;
    return limits;
}

// Each case with each integrator, and with the weld held by constraints only or, while every
// axis sticks, by O's mobilizer lock: the same oracles hold for both.
class LimitedWeldDynamics : public testing::TestWithParam<std::tuple<IntegratorKind, bool>> {
protected:
    IntegratorKind getIntegrator() const { return std::get<0>(GetParam()); }
    bool isLockable() const { return std::get<1>(GetParam()); }
};

TEST_P(LimitedWeldDynamics, HoldsAForceBelowTheLimit) {
    WeldedBox scene(isLockable());
    const double force = 0.75 * kLinearLimit;
    scene.addLoad(Vec3(0), Vec3(force, 0, 0));
    SteppedRun run(getIntegrator(), scene.system, scene.makeState(limitOn(WeldAxis::TranslationX, kLinearLimit)), 1e-6, false);
    const SimTK::State& state = run.stepTo(0.5);
    EXPECT_LT(scene.box.getBodyOriginLocation(state).norm(), kHeldDrift);
    EXPECT_LT(scene.box.getBodyVelocity(state).norm(), 1e-9);
    EXPECT_FALSE(scene.weld.isSliding(state, WeldAxis::TranslationX));
    EXPECT_EQ(scene.weld.isHeldByLock(state), isLockable());
    scene.system.realize(state, SimTK::Stage::Acceleration);
    EXPECT_NEAR(scene.weld.findWrench(state)[1][0], -force, 1e-9 * force);
    EXPECT_NEAR(scene.weld.findGeneralizedForce(state)[toIndex(WeldAxis::TranslationX)], -force, 1e-9 * force);
}

TEST_P(LimitedWeldDynamics, SlidesWithTheExcessForceAboveTheLimit) {
    WeldedBox scene(isLockable());
    const double force = -2.5 * kLinearLimit;  // along -x: the slip direction follows the load
    scene.addLoad(Vec3(0), Vec3(force, 0, 0));
    SteppedRun run(getIntegrator(), scene.system, scene.makeState(limitOn(WeldAxis::TranslationX, kLinearLimit)), 1e-6, false);
    const double t1 = 0.1, t2 = 0.3;
    const double v1 = scene.box.getBodyVelocity(run.stepTo(t1))[1][0];
    const SimTK::State& state = run.stepTo(t2);
    const double v2 = scene.box.getBodyVelocity(state)[1][0];
    const double expected = (force + kLinearLimit) / kMass;
    EXPECT_NEAR((v2 - v1) / (t2 - t1), expected, 0.02 * std::abs(expected));
    EXPECT_EQ(scene.weld.getSlideDirection(state, WeldAxis::TranslationX), -1);
    scene.system.realize(state, SimTK::Stage::Acceleration);
    EXPECT_NEAR(scene.weld.findWrench(state)[1][0], kLinearLimit, 1e-12);
    // The other axes stay stuck: no sideways motion or spin.
    EXPECT_LT(std::abs(scene.box.getBodyOriginLocation(state)[1]), kHeldDrift);
    EXPECT_LT(scene.box.getBodyAngularVelocity(state).norm(), 1e-9);
}

TEST_P(LimitedWeldDynamics, HoldsATorqueBelowTheLimit) {
    WeldedBox scene(isLockable());
    const double torque = 0.5 * kAngularLimit;
    scene.addLoad(Vec3(0, 0, torque), Vec3(0));
    SteppedRun run(getIntegrator(), scene.system, scene.makeState(limitOn(WeldAxis::RotationZ, kAngularLimit)), 1e-6, false);
    const SimTK::State& state = run.stepTo(0.5);
    EXPECT_LT(std::abs(calcAngleAboutZ(scene.box.getBodyRotation(state))), kHeldDrift);
    EXPECT_FALSE(scene.weld.isSliding(state, WeldAxis::RotationZ));
    scene.system.realize(state, SimTK::Stage::Acceleration);
    EXPECT_NEAR(scene.weld.findWrench(state)[0][2], -torque, 1e-9 * torque);
}

TEST_P(LimitedWeldDynamics, SpinsWithTheExcessTorqueAboveTheLimit) {
    WeldedBox scene(isLockable());
    const double torque = 3 * kAngularLimit;
    scene.addLoad(Vec3(0, 0, torque), Vec3(0));
    SteppedRun run(getIntegrator(), scene.system, scene.makeState(limitOn(WeldAxis::RotationZ, kAngularLimit)), 1e-6, false);
    // About 2.5 rad by t2: the axes turn with O, and z stays z.
    const double t1 = 0.2, t2 = 0.5;
    const double w1 = scene.box.getBodyVelocity(run.stepTo(t1))[0][2];
    const SimTK::State& state = run.stepTo(t2);
    const double w2 = scene.box.getBodyVelocity(state)[0][2];
    const double expected = (torque - kAngularLimit) / kInertia;
    EXPECT_NEAR((w2 - w1) / (t2 - t1), expected, 0.02 * expected);
    EXPECT_TRUE(scene.weld.isSliding(state, WeldAxis::RotationZ));
    scene.system.realize(state, SimTK::Stage::Acceleration);
    const SimTK::SpatialVec wrench = scene.weld.findWrench(state);
    EXPECT_NEAR(wrench[0][2], -kAngularLimit, 1e-12);
    EXPECT_LT(wrench[1].norm(), 1e-9);  // locked translation stays unloaded
    EXPECT_LT(scene.box.getBodyOriginLocation(state).norm(), kHeldDrift);
}

// Pushed with 2.5 L until t1, then free: O accelerates at a1 = 1.5 L / m, decelerates at L / m,
// stops at t1 + v1 m / L and sticks at x1 + v1^2 m / (2 L).
TEST_P(LimitedWeldDynamics, SticksAgainWhenTheForceDrops) {
    WeldedBox scene(isLockable());
    const double force = 2.5 * kLinearLimit, t1 = 0.1;
    scene.addLoad(Vec3(0), Vec3(force, 0, 0), t1);
    SteppedRun run(getIntegrator(), scene.system, scene.makeState(limitOn(WeldAxis::TranslationX, kLinearLimit)), 1e-6, false);
    const double a1 = (force - kLinearLimit) / kMass, v1 = a1 * t1;
    const double tStop = t1 + v1 * kMass / kLinearLimit;
    const double xStop = 0.5 * a1 * t1 * t1 + v1 * v1 * kMass / (2 * kLinearLimit);
    const SimTK::State& atT1 = run.stepTo(t1);
    EXPECT_TRUE(scene.weld.isSliding(atT1, WeldAxis::TranslationX));
    EXPECT_FALSE(scene.weld.isHeldByLock(atT1));  // the lock gave way to the slide
    const SimTK::State& sliding = run.stepTo(0.5 * (t1 + tStop));
    EXPECT_NEAR(scene.box.getBodyVelocity(sliding)[1][0], 0.5 * v1, 0.02 * 0.5 * v1);
    const SimTK::State& state = run.stepTo(tStop + 0.2);
    EXPECT_FALSE(scene.weld.isSliding(state, WeldAxis::TranslationX));
    EXPECT_NEAR(scene.box.getBodyOriginLocation(state)[0], xStop, 0.005 * xStop);
    EXPECT_LT(scene.box.getBodyVelocity(state).norm(), 1e-9);
    EXPECT_EQ(scene.weld.isHeldByLock(state), isLockable());  // and took over again
    scene.system.realize(state, SimTK::Stage::Acceleration);
    EXPECT_LT(scene.weld.findWrench(state).norm(), 1e-9);  // nothing left to resist
}

// Load along x and y with only x relaxed below it, plus a torque within rotation z's limit:
// x slides with (Fx - Lx) / m, y (locked) and rotation z (under its limit) hold, and the
// reaction is -Lx, -Fy, -Tz.
TEST_P(LimitedWeldDynamics, RelievesOnlyTheOverloadedAxis) {
    WeldedBox scene(isLockable());
    const Vec3 force(3 * kLinearLimit, 5.0, 0), torque(0, 0, 0.8 * kAngularLimit);
    scene.addLoad(torque, force);
    Vec6 limits(SimTK::Infinity);
    limits[toIndex(WeldAxis::TranslationX)] = kLinearLimit;
    limits[toIndex(WeldAxis::RotationZ)] = kAngularLimit;
    SteppedRun run(getIntegrator(), scene.system, scene.makeState(limits), 1e-6, false);
    const double t1 = 0.1, t2 = 0.2;
    const double v1 = scene.box.getBodyVelocity(run.stepTo(t1))[1][0];
    const SimTK::State& state = run.stepTo(t2);
    const double expected = (force[0] - kLinearLimit) / kMass;
    EXPECT_NEAR((scene.box.getBodyVelocity(state)[1][0] - v1) / (t2 - t1), expected, 0.02 * expected);
    EXPECT_TRUE(scene.weld.isSliding(state, WeldAxis::TranslationX));
    EXPECT_FALSE(scene.weld.isSliding(state, WeldAxis::RotationZ));
    EXPECT_LT(std::abs(scene.box.getBodyOriginLocation(state)[1]), kHeldDrift);
    EXPECT_LT(std::abs(calcAngleAboutZ(scene.box.getBodyRotation(state))), kHeldDrift);
    scene.system.realize(state, SimTK::Stage::Acceleration);
    const SimTK::SpatialVec wrench = scene.weld.findWrench(state);
    EXPECT_NEAR(wrench[1][0], -kLinearLimit, 1e-9);
    EXPECT_NEAR(wrench[1][1], -force[1], 1e-9);
    EXPECT_NEAR(wrench[0][2], -torque[2], 1e-9);
}

INSTANTIATE_TEST_SUITE_P(IntegratorsAndHolds, LimitedWeldDynamics,
                         testing::Combine(testing::Values(IntegratorKind::RungeKuttaMerson, IntegratorKind::CPodes),
                                          testing::Bool()),
                         [](const testing::TestParamInfo<std::tuple<IntegratorKind, bool>>& paramInfo) {
                             const bool cpodes = std::get<0>(paramInfo.param) == IntegratorKind::CPodes;
                             return std::string(cpodes ? "CPodes" : "RungeKuttaMerson") +
                                    (std::get<1>(paramInfo.param) ? "Lock" : "Constraints");
                         });

// Two free boxes welded with every axis locked, spinning and moving together as one rigid body
// off H's origin, a push on H alone. Oracles: the pair's mass centre accelerates with
// F / (m_H + m_O); the relative pose stays put up to integration error, which a velocity-level
// constraint does not correct, so it must shrink with the integrator's accuracy (a wrong
// constraint term would leave an accuracy-independent drift).
struct SpinningPair {
    SimTK::MultibodySystem system;
    SimTK::SimbodyMatterSubsystem matter{system};
    SimTK::GeneralForceSubsystem forces{system};
    SimTK::Body::Rigid body{SimTK::MassProperties(kMass, Vec3(0), SimTK::UnitInertia(kInertia / kMass))};
    SimTK::MobilizedBody::Free h{matter.Ground(), body};
    SimTK::MobilizedBody::Free o{matter.Ground(), body};
    LimitedWeld weld{system, matter, forces, h, SimTK::Transform(SimTK::Rotation(0.3, SimTK::YAxis), Vec3(0.05, 0, 0)),
                     o, SimTK::Transform(SimTK::Rotation(-0.2, SimTK::XAxis), Vec3(0, 0.02, 0))};
    const double push = 1.0;  // N on H along x
    const Vec3 w{1, 2, 3};    // rad/s
    const SimTK::Transform X_GO{SimTK::Rotation(0.4, SimTK::ZAxis), Vec3(0.1, 0.02, 0)};

    SpinningPair() { SimTK::Force::ConstantForce(forces, h, Vec3(0), Vec3(push, 0, 0)); }
    SimTK::State makeState() {
        SimTK::State state = system.realizeTopology();
        o.setQToFitTransform(state, X_GO);
        h.setUToFitAngularVelocity(state, w);  // H's origin at rest, O's at w x p
        o.setUToFitAngularVelocity(state, w);
        o.setUToFitLinearVelocity(state, w % X_GO.p());
        system.realize(state, SimTK::Stage::Position);
        weld.setEnabled(state, true);
        return state;
    }
    // Relative pose change after `t` s at `accuracy` (m + rad).
    double findDrift(double t, double accuracy) {
        const SimTK::State initial = makeState();
        const SimTK::Transform X_FM0 = weld.findTransform(initial);
        SteppedRun run(IntegratorKind::CPodes, system, initial, accuracy, false);
        const SimTK::State& end = run.stepTo(t);
        const SimTK::Transform X_FM = weld.findTransform(end);
        const Vec3 pCm = 0.5 * (h.getBodyOriginLocation(end) + o.getBodyOriginLocation(end));
        const Vec3 expected = 0.5 * X_GO.p() + 0.5 * (w % X_GO.p()) * t + Vec3(0.25 * push / kMass * t * t, 0, 0);
        EXPECT_LT((pCm - expected).norm(), 1e3 * accuracy);
        return (X_FM.p() - X_FM0.p()).norm() + (~X_FM0.R() * X_FM.R()).convertRotationToAngleAxis()[0];
    }
};

TEST(LimitedWeld, LockedWeldMovesTwoBodiesAsOne) {
    SpinningPair pair;
    const SimTK::State state = pair.makeState();
    EXPECT_LT((pair.weld.findEngagedTransform(state).p() - pair.weld.findTransform(state).p()).norm(), 1e-15);
    pair.system.realize(state, SimTK::Stage::Velocity);
    EXPECT_LT(pair.weld.findSlipVelocity(state).norm(), 1e-12);
    const double coarse = pair.findDrift(1.0, 1e-6), fine = pair.findDrift(1.0, 1e-8);
    EXPECT_LT(coarse, 1e-3);
    EXPECT_LT(fine, 0.1 * coarse);
}

// The constraint accelerations of a locked weld keep every slip rate at zero: r after a short
// explicit Euler step along (qdot, udot) stays zero to O(h) (a wrong velocity-derivative term,
// e.g. a missing Coriolis term, shows as an O(1) rate of change).
TEST(LimitedWeld, ConstraintAccelerationsKeepTheSlipRateZero) {
    SimTK::MultibodySystem system;
    SimTK::SimbodyMatterSubsystem matter(system);
    SimTK::GeneralForceSubsystem forces(system);
    const SimTK::Body::Rigid body(SimTK::MassProperties(kMass, Vec3(0.01, 0, 0), SimTK::UnitInertia(0.02, 0.03, 0.04)));
    SimTK::MobilizedBody::Free h(matter.Ground(), body);
    SimTK::MobilizedBody::Free o(matter.Ground(), body);
    LimitedWeld weld(system, matter, forces, h, SimTK::Transform(Vec3(0.05, 0, 0)), o,
                     SimTK::Transform(SimTK::Rotation(-0.2, SimTK::XAxis), Vec3(0, 0.02, 0)));
    SimTK::Force::ConstantForce(forces, h, Vec3(0.01, 0, 0), Vec3(1, -2, 0.5));
    SimTK::Force::ConstantTorque(forces, o, Vec3(0.3, 0.1, -0.2));
    SimTK::State state = system.realizeTopology();
    o.setQToFitTransform(state, SimTK::Transform(SimTK::Rotation(0.4, SimTK::ZAxis), Vec3(0.1, 0.02, 0)));
    h.setUToFitAngularVelocity(state, Vec3(1, 2, 3));
    o.setUToFitAngularVelocity(state, Vec3(-2, 1, 0.5));
    o.setUToFitLinearVelocity(state, Vec3(0.3, -0.1, 0.2));
    system.realize(state, SimTK::Stage::Position);
    weld.setEnabled(state, true);  // projects the relative velocity away
    system.realize(state, SimTK::Stage::Acceleration);
    ASSERT_LT(weld.findSlipVelocity(state).norm(), 1e-10);
    const double h_t = 1e-6;
    SimTK::State next = state;
    next.updQ() = state.getQ() + h_t * state.getQDot();
    next.updU() = state.getU() + h_t * state.getUDot();
    system.realize(next, SimTK::Stage::Velocity);
    const Vec6 rate = (weld.findSlipVelocity(next) - weld.findSlipVelocity(state)) / h_t;
    EXPECT_LT(rate.norm(), 1e-4) << rate;
}

// Enabling at a moving, displaced pose keeps the pose and removes only the relative velocity.
TEST(LimitedWeld, EnablingKeepsThePoseAndStopsTheRelativeMotion) {
    WeldedBox scene;
    SimTK::State state = scene.system.realizeTopology();
    const SimTK::Transform X_GO(SimTK::Rotation(0.8, SimTK::UnitVec3(1, 2, 3)), Vec3(0.1, -0.2, 0.3));
    scene.box.setQToFitTransform(state, X_GO);
    scene.box.setUToFitLinearVelocity(state, Vec3(1e-4, 0, 0));
    scene.system.realize(state, SimTK::Stage::Position);
    EXPECT_FALSE(scene.weld.isEnabled(state));
    scene.weld.setEnabled(state, true);
    EXPECT_TRUE(scene.weld.isEnabled(state));
    EXPECT_LT((scene.box.getBodyTransform(state).p() - X_GO.p()).norm(), 1e-15);
    EXPECT_LT((scene.weld.findEngagedTransform(state).p() - X_GO.p()).norm(), 1e-15);
    scene.system.realize(state, SimTK::Stage::Velocity);
    EXPECT_LT(scene.box.getBodyVelocity(state).norm(), 1e-10);
}

// The lock's reaction, read from its motion forces in the mobilizer's frames, against the six
// constraints' multipliers (second method) for the same pose and load, with F, M and the
// mobilizer's frames all apart and turned: H a base welded to Ground at a turned pose, O either
// H's child (lock) or Ground's (constraints) at the same pose in Ground, under gravity and a
// load off its centre. Every axis locked, so both hold.
struct OffsetWeld {
    explicit OffsetWeld(bool onBase)
        : box(onBase ? static_cast<SimTK::MobilizedBody&>(base) : static_cast<SimTK::MobilizedBody&>(matter.updGround()),
              SimTK::Transform(SimTK::Rotation(0.3, SimTK::XAxis), Vec3(0.01, 0, 0)),
              SimTK::Body::Rigid(SimTK::MassProperties(kMass, Vec3(0.01, -0.02, 0), SimTK::UnitInertia(0.02, 0.03, 0.04))),
              SimTK::Transform(SimTK::Rotation(-0.5, SimTK::YAxis), Vec3(0, 0.02, 0.01))),
          weld(system, matter, forces, base, X_HF, box, X_OM),
          lockable(onBase) {
        SimTK::Force::Gravity(forces, matter, SimTK::UnitVec3(0.2, -1, 0.1), 9.81);
        SimTK::Force::ConstantForce(forces, box, Vec3(0.03, 0.01, -0.02), Vec3(1, -2, 0.5));
        SimTK::Force::ConstantTorque(forces, box, Vec3(0.3, 0.1, -0.2));
    }
    // The weld's reaction on O at pose X_GO, in Ground.
    SimTK::SpatialVec findWrench(const SimTK::Transform& X_GO) {
        SimTK::State state = system.realizeTopology();
        const SimTK::Transform X_PO = lockable ? ~X_GB * X_GO : X_GO;  // in O's parent
        box.setQToFitTransform(state, ~box.getInboardFrame(state) * X_PO * box.getOutboardFrame(state));
        system.realize(state, SimTK::Stage::Position);
        EXPECT_LT((box.getBodyTransform(state).p() - X_GO.p()).norm(), 1e-12);
        weld.setEnabled(state, true);
        EXPECT_EQ(weld.isHeldByLock(state), lockable);
        system.realize(state, SimTK::Stage::Acceleration);
        return weld.findWrench(state);
    }

    SimTK::MultibodySystem system;
    SimTK::SimbodyMatterSubsystem matter{system};
    SimTK::GeneralForceSubsystem forces{system};
    const SimTK::Transform X_GB{SimTK::Rotation(0.7, SimTK::UnitVec3(1, 1, 0)), Vec3(0.1, 0.2, -0.1)};
    SimTK::MobilizedBody::Weld base{matter.Ground(), X_GB, SimTK::Body::Rigid(SimTK::MassProperties(1, Vec3(0), SimTK::UnitInertia(1))), SimTK::Transform()};
    SimTK::MobilizedBody::Free box;
    const SimTK::Transform X_HF{SimTK::Rotation(0.2, SimTK::ZAxis), Vec3(0.05, 0, 0)};
    const SimTK::Transform X_OM{SimTK::Rotation(-0.4, SimTK::XAxis), Vec3(0, 0.03, 0.02)};
    LimitedWeld weld;
    bool lockable;
};

TEST(LimitedWeld, LockReactionEqualsTheConstraintReaction) {
    const SimTK::Transform X_GO(SimTK::Rotation(0.9, SimTK::UnitVec3(1, 2, 3)), Vec3(0.12, 0.17, -0.06));
    OffsetWeld locked(true), constrained(false);
    const SimTK::SpatialVec byLock = locked.findWrench(X_GO), byConstraints = constrained.findWrench(X_GO);
    EXPECT_GT(byLock.norm(), 1.0);
    EXPECT_LT((byLock - byConstraints).norm(), 1e-9 * byConstraints.norm()) << byLock << " vs " << byConstraints;
}

TEST(LimitedWeld, DisabledWeldAppliesNothing) {
    WeldedBox scene;
    const double force = 1.0;
    scene.addLoad(Vec3(0), Vec3(force, 0, 0));
    SimTK::State state = scene.makeState(limitOn(WeldAxis::TranslationX, 0.1));
    EXPECT_TRUE(scene.weld.isSliding(state, WeldAxis::TranslationX));  // 1 N > 0.1 N at once
    scene.weld.setEnabled(state, false);
    scene.system.realize(state, SimTK::Stage::Acceleration);
    EXPECT_FALSE(scene.weld.isSliding(state, WeldAxis::TranslationX));
    EXPECT_EQ(scene.weld.findWrench(state).norm(), 0);
    EXPECT_NEAR(scene.box.getBodyAcceleration(state)[1][0], force / kMass, 1e-12);
}

TEST(LimitedWeld, RejectsBadInputNamingTheAxis) {
    WeldedBox scene;
    SimTK::State state = scene.system.realizeTopology();
    try {
        scene.weld.setLimits(state, Vec6(1, 1, 1, 1, -2, 1));
        FAIL() << "negative limit accepted";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("limit on translation y is -2"), std::string::npos) << error.what();
    }
    EXPECT_THROW(scene.weld.setLimits(state, Vec6(SimTK::NaN, 1, 1, 1, 1, 1)), InputError);
    EXPECT_THROW(LimitedWeld(scene.system, scene.matter, scene.forces, scene.box, SimTK::Transform(), scene.box,
                             SimTK::Transform()),
                 InputError);
}

}  // namespace
}  // namespace graspsim::grasp
