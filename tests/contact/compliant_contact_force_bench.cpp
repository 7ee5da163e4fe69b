// Cost of one evaluation of the compliant contact force for the anthropometric right hand
// (17 geometries: 15 phalanx capsules, 2 palm boxes) against a ball, a phone, or a cylinder,
// ellipsoid or convex mesh object: 17 pairs. And the cost of one contact query of a fingertip
// pressed 1 mm into each object shape. Speed is measured here, never asserted in unit tests.

#include <benchmark/benchmark.h>
#include <simbody/Simbody.h>

#include <memory>

#include "graspsim/contact/compliant_contact_force.h"
#include "graspsim/contact/hand_object_pairs.h"
#include "graspsim/contact/shape_contact.h"
#include "graspsim/contact/surface_point.h"
#include "test_meshes.h"
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
                                         contact::ContactParameters{}));
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

// The ball model with its geometry replaced by `geometry` (same mass and body name).
model::ModelDescription makeObjectModel(model::Geometry geometry) {
    model::ModelDescription description = model::buildBallModel();
    geometry.name = "object";
    description.bodies.front().geometry = {geometry};
    return description;
}

model::Geometry makeGeometry(model::Geometry::Type type) {
    model::Geometry g;
    g.type = type;
    g.radius = 0.03;
    g.length = 0.12;
    g.semiAxes = {0.045, 0.035, 0.03};
    if (type == model::Geometry::Type::Mesh) {
        g.mesh = std::make_shared<model::TriangleMesh>(contact::test::makeCylinderMesh(0.03, 0.12, 64));
    }
    return g;
}

void BM_HandObjectInHand(benchmark::State& s, model::Geometry::Type type) {
    runForceEvaluation(s, makeObjectModel(makeGeometry(type)), true);
}

// A fingertip sphere (8 mm) 1 mm into the object's side: one findContacts call.
void BM_FingertipContact(benchmark::State& bench, model::Geometry::Type type) {
    const contact::ContactShape object = contact::ContactShape::fromGeometry(makeGeometry(type));
    const contact::ContactShape tip = contact::ContactShape::sphere(0.008);
    const SimTK::Vec3 direction = SimTK::UnitVec3(1, 0.3, 0.2);
    const double surface = -contact::findSurfacePoint(object, SimTK::Vec3(0)).distance;  // rough
    SimTK::Vec3 centre = direction * surface;
    // Move along the direction until the tip is 1 mm deep (surface distance 7 mm).
    for (int i = 0; i < 50; ++i) {
        centre += direction * (0.007 - contact::findSurfacePoint(object, centre).distance);
    }
    const SimTK::Transform X_GT(centre);
    std::vector<contact::ContactPoint> contacts;
    for (auto _ : bench) {
        contacts.clear();
        contact::appendContacts(tip, X_GT, object, SimTK::Transform(), contacts);
        benchmark::DoNotOptimize(contacts.data());
    }
    bench.counters["depth_mm"] = contacts.empty() ? 0 : 1000 * contacts[0].depth;
}

BENCHMARK_CAPTURE(BM_FingertipContact, sphere, model::Geometry::Type::Sphere);
BENCHMARK_CAPTURE(BM_FingertipContact, cylinder, model::Geometry::Type::Cylinder);
BENCHMARK_CAPTURE(BM_FingertipContact, ellipsoid, model::Geometry::Type::Ellipsoid);
BENCHMARK_CAPTURE(BM_FingertipContact, mesh_cylinder_64, model::Geometry::Type::Mesh);
BENCHMARK_CAPTURE(BM_HandObjectInHand, cylinder, model::Geometry::Type::Cylinder)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_HandObjectInHand, ellipsoid, model::Geometry::Type::Ellipsoid)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_HandObjectInHand, mesh_cylinder_64, model::Geometry::Type::Mesh)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_HandBallFar)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_HandBallInHand)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_HandPhoneFar)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_HandPhoneInHand)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
