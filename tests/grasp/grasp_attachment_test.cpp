// The contract every GraspAttachment keeps, checked on each of the three (one parameterized
// suite): an object O of mass m, free in space (gravity off), attached to Ground (the "palm")
// with friction limit L along x (every other axis locked or carrying no load), pulled along x by
// a constant force F at its centre of mass. Closed forms (Coulomb friction per axis):
//  - F < L: O is held (a rigid attachment does not move; a compliant one deflects F / K and stays);
//  - F > L: O slides with a = (F - L) / m, the attachment carrying exactly its limit;
//  - releasing lets go without changing O's velocity; afterwards a = F / m.
#include "graspsim/grasp/grasp_attachment.h"

#include "graspsim/grasp/limited_bushing.h"
#include "graspsim/grasp/limited_weld.h"
#include "graspsim/grasp/multi_attachment.h"

#include "stepped_run.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

namespace graspsim::grasp {
namespace {

using SimTK::Vec3;
using SimTK::Vec6;

enum class AttachmentKind { Bushing, Weld, Multi };

std::string toName(const testing::TestParamInfo<AttachmentKind>& info) {
    switch (info.param) {
    case AttachmentKind::Bushing: return "Bushing";
    case AttachmentKind::Weld: return "Weld";
    case AttachmentKind::Multi: return "Multi";
    }
    return "Unknown";
}

constexpr double kMass = 0.5;         // kg
constexpr double kLimit = 2.0;        // N, friction limit along x
constexpr double kMu = 0.5;           // multi: the part's limit is mu N
constexpr double kSqueeze = kLimit / kMu;  // N, the multi part's normal force
constexpr double kFrequency = 200.0;  // rad/s, the compliant attachments' natural frequency
const double kInertia = kMass * 1e-3;  // kg m^2, each central moment

// Lets go of the object at `time`, recording O's velocity just before and as the integrator
// restarts from it (realized and projected, as the TimeStepper does after a handler).
class ReleaseAt : public SimTK::ScheduledEventHandler {
public:
    ReleaseAt(const GraspAttachment& attachment, const SimTK::MobilizedBody& object, double time)
        : attachment_(attachment), object_(object), time_(time) {}
    SimTK::Real getNextEventTime(const SimTK::State&, bool) const override { return time_; }
    void handleEvent(SimTK::State& state, SimTK::Real, bool& shouldTerminate) const override {
        shouldTerminate = false;
        const SimTK::System& system = object_.getMatterSubsystem().getSystem();
        system.realize(state, SimTK::Stage::Velocity);
        before = object_.getBodyOriginVelocity(state);
        attachment_.release(state);
        system.realize(state, SimTK::Stage::Velocity);
        system.projectU(state, 1e-12);
        system.realize(state, SimTK::Stage::Velocity);
        after = object_.getBodyOriginVelocity(state);
    }
    mutable Vec3 before{SimTK::NaN}, after{SimTK::NaN};  // written by the handler, read by the test

private:
    const GraspAttachment& attachment_;
    SimTK::MobilizedBody object_;
    double time_;
};

// The rig, with the attachment of one kind between Ground and O, engaged at t = 0.
struct PulledObject {
    SimTK::MultibodySystem system;
    SimTK::SimbodyMatterSubsystem matter{system};
    SimTK::GeneralForceSubsystem forces{system};
    SimTK::MobilizedBody::Free object;
    LimitedBushing bushing;
    std::unique_ptr<LimitedWeld> weld;
    std::unique_ptr<MultiAttachment> multi;
    const GraspAttachment* attachment = nullptr;
    ReleaseAt* release = nullptr;  // owned by the System
    AttachmentKind kind;

    PulledObject(AttachmentKind k, double load, double releaseTime) : kind(k) {
        const SimTK::Body::Rigid body(SimTK::MassProperties(kMass, Vec3(0), SimTK::UnitInertia(kInertia / kMass)));
        object = SimTK::MobilizedBody::Free(matter.Ground(), body);
        SimTK::Force::ConstantForce(forces, object, Vec3(0), Vec3(load, 0, 0));
        const double w2 = kFrequency * kFrequency;
        const Vec6 stiffness(kInertia * w2, kInertia * w2, kInertia * w2, kMass * w2, kMass * w2, kMass * w2);
        const Vec6 damping(2 * kInertia * kFrequency, 2 * kInertia * kFrequency, 2 * kInertia * kFrequency,
                           2 * kMass * kFrequency, 2 * kMass * kFrequency, 2 * kMass * kFrequency);
        if (kind == AttachmentKind::Bushing) {
            bushing = LimitedBushing(forces, matter.Ground(), SimTK::Transform(), object, SimTK::Transform(), stiffness,
                                     damping);
            attachment = &bushing;
        } else if (kind == AttachmentKind::Weld) {
            weld = std::make_unique<LimitedWeld>(system, matter, forces, matter.Ground(), SimTK::Transform(), object,
                                                 SimTK::Transform());
            attachment = weld.get();
        } else {
            // Site at O's origin, outward normal z, x along the load.
            const AttachmentSite site{matter.Ground(), Vec3(0), SimTK::UnitVec3(0, 0, 1), Vec3(1, 0, 0)};
            multi = std::make_unique<MultiAttachment>(forces, object, std::vector<AttachmentSite>{site}, stiffness,
                                                      damping);
            attachment = multi.get();
        }
        if (releaseTime > 0) {
            release = new ReleaseAt(*attachment, object, releaseTime);
            system.addEventHandler(release);
        }
    }

    AttachmentEngagement makeEngagement() const {
        AttachmentEngagement e;
        e.limits = Vec6(1, 1, 1, kLimit, kLimit, kLimit);  // N m, N
        e.lockedAxes = {true, true, true, false, true, true};
        e.penetrationBound = 1;  // m: loose, so the compliant ones keep the rig's stiffness
        FingerLoad finger;
        finger.normalForce = kSqueeze;  // limit mu N = kLimit on the tangents
        finger.armRadius = 1;           // m: rotation limits mu r N, far above the (zero) moment
        finger.tangentHint_G = Vec3(1, 0, 0);
        e.fingers = {finger};
        e.mu = kMu;
        return e;
    }

    SimTK::State makeEngagedState() {
        SimTK::State state = system.realizeTopology();
        attachment->release(state);
        system.realize(state, SimTK::Stage::Position);
        attachment->engage(state, makeEngagement());
        return state;
    }
    double getX(const SimTK::State& s) const { return object.getBodyOriginLocation(s)[0]; }
    double getSpeed(const SimTK::State& s) const { return object.getBodyOriginVelocity(s)[0]; }
};

class GraspAttachmentContract : public testing::TestWithParam<AttachmentKind> {};

TEST_P(GraspAttachmentContract, HoldsBelowTheLimit) {
    const double load = 0.5 * kLimit;
    PulledObject rig(GetParam(), load, 0);
    const SimTK::State initial = rig.makeEngagedState();
    EXPECT_TRUE(rig.attachment->isEngaged(initial));
    test::SteppedRun run(test::IntegratorKind::RungeKuttaMerson, rig.system, initial);
    const SimTK::State& state = run.stepTo(1.0);
    rig.system.realize(state, SimTK::Stage::Acceleration);
    // Rigid: no motion; compliant: the static deflection F / K (critically damped, settled
    // after 200 periods).
    const double deflection = rig.kind == AttachmentKind::Weld ? 0.0 : load / (kMass * kFrequency * kFrequency);
    EXPECT_NEAR(rig.getX(state), deflection, 1e-3 * load / (kMass * kFrequency * kFrequency));
    EXPECT_NEAR(rig.getSpeed(state), 0, 1e-6);
    EXPECT_FALSE(rig.attachment->isSliding(state, BushingAxis::TranslationX));
    // The attachment balances the load: its reaction on O is -F along x.
    EXPECT_NEAR(rig.attachment->findReactionOnObject(state)[1][0], -load, 1e-3 * load);
}

TEST_P(GraspAttachmentContract, SlidesAtTheLimitWithTheAnalyticAcceleration) {
    const double load = 2 * kLimit;
    PulledObject rig(GetParam(), load, 0);
    test::SteppedRun run(test::IntegratorKind::RungeKuttaMerson, rig.system, rig.makeEngagedState());
    const double v1 = rig.getSpeed(run.stepTo(0.5));
    const SimTK::State& state = run.stepTo(1.0);
    const double v2 = rig.getSpeed(state);
    const double a = (load - kLimit) / kMass;  // closed form: Coulomb friction at the limit
    EXPECT_NEAR((v2 - v1) / 0.5, a, 1e-3 * a);
    rig.system.realize(state, SimTK::Stage::Acceleration);
    EXPECT_TRUE(rig.attachment->isSliding(state, BushingAxis::TranslationX));
    EXPECT_NEAR(rig.attachment->findReactionOnObject(state)[1][0], -kLimit, 1e-3 * kLimit);
}

TEST_P(GraspAttachmentContract, ReleasesWithoutAVelocityJump) {
    const double load = 2 * kLimit;  // sliding, so O moves when released
    const double releaseTime = 0.5;
    PulledObject rig(GetParam(), load, releaseTime);
    test::SteppedRun run(test::IntegratorKind::RungeKuttaMerson, rig.system, rig.makeEngagedState(), 1e-6, false);
    const double v1 = rig.getSpeed(run.stepTo(releaseTime));
    EXPECT_FALSE(rig.attachment->isEngaged(run.stepTo(releaseTime + 1e-9)));
    EXPECT_GT(rig.release->before[0], 0.1);  // moving at the release
    EXPECT_LT((rig.release->after - rig.release->before).norm(), 1e-12);
    const double v2 = rig.getSpeed(run.stepTo(1.0));
    EXPECT_NEAR((v2 - v1) / (1.0 - releaseTime), load / kMass, 1e-6 * load / kMass);  // free: a = F / m
}

INSTANTIATE_TEST_SUITE_P(EveryAttachment, GraspAttachmentContract,
                         testing::Values(AttachmentKind::Bushing, AttachmentKind::Weld, AttachmentKind::Multi), toName);

}  // namespace
}  // namespace graspsim::grasp
