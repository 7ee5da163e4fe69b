#include "graspsim/simulation/grasp_approximation.h"

#include "graspsim/error.h"

namespace graspsim::simulation {

namespace {

const grasp::GraspAttachment& findAttachment(const GraspScene& scene) {
    if (!scene.getAttachment()) throw Error("grasp approximation: the scene has no attachment (not an approx-mode scene)");
    return *scene.getAttachment();
}

ApproximationContext makeContext(const GraspScene& scene) {
    const scenario::Scenario& s = scene.getScenario();
    const auto& g = s.world.gravity;
    return ApproximationContext{scene.getModel(),
                                scene.getObject(),
                                scene.getPalm(),
                                scene.getFingerMobilizers(),
                                scene.getCompliantContacts(),
                                scene.getContactParameters(),
                                s.object,
                                SimTK::Vec3(g[0], g[1], g[2]),
                                scene.getFingertipGoals(),
                                scene.getObjectHold(),
                                s.simulation.settleTime,
                                s.simulation.heldTolerance,
                                findAttachment(scene),
                                scene.getMultiAttachment(),
                                scene.getController(),
                                s.controller.ikInterval};
}

}  // namespace

GraspApproximation::GraspApproximation(GraspScene& scene, const ApproxOptions& options) : context_(makeContext(scene)) {
    system::MultibodyModel& model = scene.updModel();
    switch_ = new GraspSwitch(context_, model.updForces(), options);
    model.updSystem().addEventHandler(switch_);
    if (SimTK::TriggeredEventHandler* witness = switch_->makeDetachWitness()) model.updSystem().addEventHandler(witness);
    model.realizeTopology();
}

}  // namespace graspsim::simulation
