// MultiAttachment in a reduced scene with closed-form oracles: an object O on a vertical slider,
// squeezed by two "fingers" on horizontal sliders, each pushed toward O by a constant force N,
// and loaded along the slider by a constant force F (gravity off). Each finger's part has the
// limit mu N, so O holds for F < 2 mu N (static deflection F / 2K) and slides with
// (F - 2 mu N) / m above; once a finger is detached, O slides with (F - mu N) / m and that finger
// no longer follows O: only its own push N accelerates it.
#include "graspsim/grasp/multi_attachment.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "graspsim/error.h"

namespace graspsim::grasp {
namespace {

using SimTK::Vec3;
using SimTK::Vec6;

constexpr double kObjectMass = 0.2;   // kg
constexpr double kFingerMass = 0.02;  // kg
constexpr double kHalfWidth = 0.01;   // m, O's centre to each site
constexpr double kSqueeze = 4;        // N, each finger's push toward O
constexpr double kMu = 0.5;
constexpr double kStiffness = 2e3;    // N/m, every translation axis of a part
const double kSharedLimit = 2 * kMu * kSqueeze;  // N, the two parts' tangent limits together
// Critical damping: along the slider O sees two parts in parallel; along its slider a finger sees one.
const double kTangentDamping = std::sqrt(2 * kStiffness * kObjectMass);
const double kNormalDamping = 2 * std::sqrt(kStiffness * kFingerMass);

// O slides along Ground y (a Slider translates along its frames' x: both frames turned 90 deg
// about z, so O keeps Ground's orientation); finger k on the side s_k = -1, +1 slides along x.
struct SqueezedObject {
    SimTK::MultibodySystem system;
    SimTK::SimbodyMatterSubsystem matter{system};
    SimTK::GeneralForceSubsystem forces{system};
    SimTK::MobilizedBody::Slider object;
    SimTK::MobilizedBody::Slider fingers[2];
    MultiAttachment attachment;

    explicit SqueezedObject(double load) {
        const SimTK::Transform X_vertical(SimTK::Rotation(SimTK::Pi / 2, SimTK::ZAxis));
        object = SimTK::MobilizedBody::Slider(matter.Ground(), X_vertical, makeBody(kObjectMass), X_vertical);
        std::vector<AttachmentSite> sites;
        for (int k = 0; k < 2; ++k) {
            const double side = k == 0 ? -1 : 1;
            fingers[k] = SimTK::MobilizedBody::Slider(matter.Ground(), SimTK::Transform(Vec3(side * kHalfWidth, 0, 0)),
                                                      makeBody(kFingerMass), SimTK::Transform());
            SimTK::Force::ConstantForce(forces, fingers[k], Vec3(0), Vec3(-side * kSqueeze, 0, 0));
            sites.push_back({fingers[k], Vec3(side * kHalfWidth, 0, 0), SimTK::UnitVec3(side, 0, 0), Vec3(0, 1, 0)});
        }
        SimTK::Force::ConstantForce(forces, object, Vec3(0), Vec3(0, load, 0));
        const Vec6 stiffness(1, 1, 1, kStiffness, kStiffness, kStiffness);
        const Vec6 damping(0.01, 0.01, 0.01, kTangentDamping, kTangentDamping, kNormalDamping);
        attachment = MultiAttachment(forces, object, sites, stiffness, damping);
    }
    static SimTK::Body::Rigid makeBody(double mass) {
        return SimTK::Body::Rigid(SimTK::MassProperties(mass, Vec3(0), SimTK::UnitInertia(1e-4)));
    }
    // Both fingers attached, each preloaded with the push it exerts on O.
    SimTK::State makeState() {
        SimTK::State state = system.realizeTopology();
        attachment.detachAll(state);
        for (int k = 0; k < 2; ++k) {
            const double side = k == 0 ? -1 : 1;
            FingerLoad load;
            load.force_G = Vec3(-side * kSqueeze, 0, 0);
            load.normalForce = kSqueeze;
            attachment.attach(state, k, load, kMu);
        }
        return state;
    }
    double getHeight(const SimTK::State& s) const { return object.getOneQ(s, SimTK::MobilizerQIndex(0)); }
    double getSpeed(const SimTK::State& s) const { return object.getOneU(s, SimTK::MobilizerUIndex(0)); }
    double getFingerSpeed(const SimTK::State& s, int k) const { return fingers[k].getOneU(s, SimTK::MobilizerUIndex(0)); }
};

// Detaches finger 1 at a given time (an Instance-stage change, so from an event handler).
class DetachAt : public SimTK::ScheduledEventHandler {
public:
    DetachAt(const MultiAttachment& attachment, double time) : attachment_(attachment), time_(time) {}
    SimTK::Real getNextEventTime(const SimTK::State&, bool) const override { return time_; }
    void handleEvent(SimTK::State& state, SimTK::Real, bool& shouldTerminate) const override {
        shouldTerminate = false;
        attachment_.detach(state, 1);
    }

private:
    const MultiAttachment& attachment_;
    double time_;
};

class SteppedRun {
public:
    SteppedRun(const SimTK::MultibodySystem& system, const SimTK::State& initial) : integrator_(system) {
        integrator_.setAccuracy(1e-7);
        stepper_ = std::make_unique<SimTK::TimeStepper>(system, integrator_);
        stepper_->initialize(initial);
    }
    const SimTK::State& stepTo(double t) {
        stepper_->stepTo(t);
        return stepper_->getState();
    }

private:
    SimTK::RungeKuttaMersonIntegrator integrator_;
    std::unique_ptr<SimTK::TimeStepper> stepper_;
};

TEST(MultiAttachment, AttachingPreloadsThePushWithoutAJump) {
    SqueezedObject scene(0);
    const SimTK::State state = scene.makeState();
    scene.system.realize(state, SimTK::Stage::Acceleration);
    for (int k = 0; k < 2; ++k) {
        EXPECT_NEAR(scene.attachment.findPressingForce(state, k), kSqueeze, 1e-9 * kSqueeze);
        EXPECT_NEAR(scene.fingers[k].getBodyAcceleration(state)[1].norm(), 0, 1e-9);
    }
    EXPECT_EQ(scene.attachment.countAttached(state), 2);
}

TEST(MultiAttachment, HoldsBelowTheSharedLimit) {
    const double load = 0.75 * kSharedLimit;  // more than one finger alone could hold
    SqueezedObject scene(load);
    SteppedRun run(scene.system, scene.makeState());
    const SimTK::State& state = run.stepTo(0.5);  // about 50 time constants
    EXPECT_NEAR(scene.getHeight(state), load / (2 * kStiffness), 1e-3 * load / (2 * kStiffness));
    EXPECT_NEAR(scene.getSpeed(state), 0, 1e-6);
    for (int k = 0; k < 2; ++k) {
        EXPECT_NEAR(scene.attachment.findPressingForce(state, k), kSqueeze, 1e-6);
        EXPECT_LT(scene.attachment.findSlide(state, k), 1e-6);
    }
}

TEST(MultiAttachment, SlidesWithTheExcessForceAboveTheSharedLimit) {
    const double load = 1.5 * kSharedLimit;
    SqueezedObject scene(load);
    SteppedRun run(scene.system, scene.makeState());
    const double t1 = 0.1, t2 = 0.3;
    const double v1 = scene.getSpeed(run.stepTo(t1));
    const SimTK::State& state = run.stepTo(t2);
    const double expected = (load - kSharedLimit) / kObjectMass;
    EXPECT_NEAR((scene.getSpeed(state) - v1) / (t2 - t1), expected, 1e-3 * expected);
    // The object's travel is each part's slip plus its elastic stretch at the limit mu N / K.
    const double elastic = kMu * kSqueeze / kStiffness;
    for (int k = 0; k < 2; ++k) {
        EXPECT_NEAR(scene.attachment.findSlide(state, k), scene.getHeight(state) - elastic, 1e-3 * scene.getHeight(state));
    }
}

TEST(MultiAttachment, ADetachedFingerStopsCarryingLoadAndFollowing) {
    const double load = 0.75 * kSharedLimit;  // held by two fingers, too much for one
    SqueezedObject scene(load);
    const double tDetach = 0.2;
    scene.system.addEventHandler(new DetachAt(scene.attachment, tDetach));
    SteppedRun run(scene.system, scene.makeState());
    EXPECT_NEAR(scene.getSpeed(run.stepTo(tDetach - 1e-3)), 0, 1e-6);  // held by two
    const double t1 = 0.3, t2 = 0.5;
    const SimTK::State s1 = run.stepTo(t1);
    const SimTK::State& s2 = run.stepTo(t2);
    EXPECT_FALSE(scene.attachment.isAttached(s2, 1));
    EXPECT_EQ(scene.attachment.findPressingForce(s2, 1), 0);
    // The remaining finger's limit alone: O slides with (F - mu N) / m.
    const double expected = (load - kMu * kSqueeze) / kObjectMass;
    EXPECT_NEAR((scene.getSpeed(s2) - scene.getSpeed(s1)) / (t2 - t1), expected, 1e-3 * expected);
    // The detached finger (side +1) moves only under its own push -N.
    const double fingerAcceleration = (scene.getFingerSpeed(s2, 1) - scene.getFingerSpeed(s1, 1)) / (t2 - t1);
    EXPECT_NEAR(fingerAcceleration, -kSqueeze / kFingerMass, 1e-9 * kSqueeze / kFingerMass);
    EXPECT_NEAR(scene.attachment.findPressingForce(s2, 0), kSqueeze, 1e-3 * kSqueeze);
}

TEST(MultiAttachment, RejectsNoSiteAndAMissingPart) {
    SimTK::MultibodySystem system;
    SimTK::SimbodyMatterSubsystem matter(system);
    SimTK::GeneralForceSubsystem forces(system);
    const SimTK::MobilizedBody::Free object(matter.Ground(), SqueezedObject::makeBody(1));
    const Vec6 ones(1, 1, 1, 1, 1, 1);
    EXPECT_THROW(MultiAttachment(forces, object, {}, ones, ones), InputError);
    const MultiAttachment attachment(forces, object, {{matter.Ground(), Vec3(0), SimTK::UnitVec3(0, 0, 1), Vec3(0)}},
                                     ones, ones);
    EXPECT_THROW(attachment.getPart(1), InputError);
}

}  // namespace
}  // namespace graspsim::grasp
