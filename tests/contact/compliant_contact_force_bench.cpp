// Cost of one evaluation of the compliant contact force for the anthropometric right hand
// (17 geometries: 15 phalanx capsules, 2 palm boxes) against a ball or a phone: 17 pairs.
// Speed is measured here, never asserted in unit tests.

#include <benchmark/benchmark.h>
#include <simbody/Simbody.h>

#include <memory>

#include "graspsim/contact/compliant_contact_force.h"
#include "graspsim/contact/hand_object_pairs.h"
#include "graspsim/model/body_model.h"
#include "graspsim/model/object_model.h"

namespace {

using namespace graspsim;

// The arm at zero joint angles with a free object; the object's centre is put at the mean of
// the hand geometry centres (so it overlaps the palm and several phalanges) or far away.
struct HandWithObject {
    system::MultibodyModel arm{model::buildBodyModel(model::BuildOptions{})};
    model::Body object;
    SimTK::MobilizedBody::Free objectMobod;
    contact::CompliantContactForce force;
    SimTK::State state;

    HandWithObject(const model::ModelDescription& objectModel, bool inHand) {
        object = objectModel.bodies.front();
        objectMobod =
            SimTK::MobilizedBody::Free(arm.updMatter().updGround(),
                                       SimTK::Body::Rigid(SimTK::MassProperties(
                                           object.mass, SimTK::Vec3(0), SimTK::UnitInertia(1e-4))));
        force = contact::CompliantContactForce(
            arm.updForces(),
            contact::makeHandObjectPairs(arm, contact::isHandSegmentBody, objectMobod, object,
                                         contact::ContactMaterial::fingerPad(),
                                         contact::ContactMaterial::rigidPlastic()));
        state = arm.realizeTopology();
        arm.getSystem().realize(state, SimTK::Stage::Position);
        const SimTK::Vec3 centre = inHand ? findHandCentre() : SimTK::Vec3(1, 1, 1);
        objectMobod.setQToFitTransform(
            state, SimTK::Transform(SimTK::Rotation(0.3, SimTK::XAxis), centre));
        objectMobod.setUToFitLinearVelocity(state, SimTK::Vec3(0.01, -0.02, 0.005));
        arm.getSystem().realize(state, SimTK::Stage::Velocity);
    }

    SimTK::Vec3 findHandCentre() const {
        SimTK::Vec3 sum(0);
        int count = 0;
        for (int i = 0; i < force.getNumPairs(); ++i) {
            const contact::ContactSurface& hand = force.getPair(i).a;
            sum += (hand.body.getBodyTransform(state) * hand.X_BS).p();
            ++count;
        }
        return sum / count;
    }
};

void runForceEvaluation(benchmark::State& bench, const model::ModelDescription& object,
                        bool inHand) {
    HandWithObject scene(object, inHand);
    const SimTK::SimbodyMatterSubsystem& matter = scene.arm.getMatter();
    SimTK::Vector_<SimTK::SpatialVec> bodyForces(matter.getNumBodies());
    SimTK::Vector_<SimTK::Vec3> particleForces(0);
    SimTK::Vector mobilityForces(matter.getNumMobilities());
    for (auto _ : bench) {
        scene.force.calcForceContribution(scene.state, bodyForces, particleForces, mobilityForces);
        benchmark::DoNotOptimize(bodyForces);
    }
    bench.counters["pairs"] = scene.force.getNumPairs();
    bench.counters["contacts"] =
        static_cast<double>(scene.force.findContactReports(scene.state).size());
}

void BM_HandBallFar(benchmark::State& s) { runForceEvaluation(s, model::buildBallModel(), false); }
void BM_HandBallInHand(benchmark::State& s) {
    runForceEvaluation(s, model::buildBallModel(), true);
}
void BM_HandPhoneFar(benchmark::State& s) {
    runForceEvaluation(s, model::buildPhoneModel(), false);
}
void BM_HandPhoneInHand(benchmark::State& s) {
    runForceEvaluation(s, model::buildPhoneModel(), true);
}

BENCHMARK(BM_HandBallFar)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_HandBallInHand)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_HandPhoneFar)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_HandPhoneInHand)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
