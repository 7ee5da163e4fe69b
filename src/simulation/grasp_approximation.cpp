#include "graspsim/simulation/grasp_approximation.h"

#include "graspsim/error.h"
#include "graspsim/grasp/limited_bushing_law.h"
#include "graspsim/system/simtk_conversion.h"

namespace graspsim::simulation {

namespace {

using system::toSimTKVec3;

// Stiffness per bushing axis (rotation first) giving the body natural frequency w (rad/s) about
// and along its central principal axes: I_k w^2 and m w^2.
SimTK::Vec6 calcBushingStiffness(const SimTK::MassProperties& mp, double w) {
    const SimTK::Vec3 I = mp.calcCentralInertia().getMoments();
    SimTK::Vec6 stiffness;
    for (int k = 0; k < 3; ++k) {
        stiffness[k] = I[k] * w * w;
        stiffness[k + 3] = mp.getMass() * w * w;
    }
    return stiffness;
}

// One site per goal, at the goal on the surface, normal outward, x along gravity's tangent part
// (the main load: the per-axis limits are exact along it).
std::vector<grasp::AttachmentSite> findAttachmentSites(const GraspScene& scene) {
    const scenario::Scenario& s = scene.getScenario();
    const model::ModelDescription& d = scene.getModel().getDescription();
    const SimTK::Rotation R_OG = ~system::toSimTKTransform(s.object.findPose(), "object pose").R();
    const SimTK::Vec3 g_O = R_OG * toSimTKVec3(s.world.gravity);
    std::vector<grasp::AttachmentSite> sites;
    for (const auto& [endEffector, p_OT] : s.goals) {
        const model::Vec3 n = s.object.findOutwardNormal(p_OT);
        sites.push_back({scene.getModel().getMobilizedBody(d.findEndEffector(endEffector)->body), toSimTKVec3(p_OT),
                         SimTK::UnitVec3(toSimTKVec3(n)), g_O});
    }
    return sites;
}

ApproximationContext makeContext(const GraspScene& scene, const grasp::GraspAttachment& attachment,
                                 const grasp::MultiAttachment* multi) {
    const scenario::Scenario& s = scene.getScenario();
    return ApproximationContext{scene.getModel(),
                                scene.getObject(),
                                scene.getPalm(),
                                scene.getFingerMobilizers(),
                                scene.getCompliantContacts(),
                                scene.getContactParameters(),
                                toSimTKVec3(s.world.gravity),
                                scene.getFingertipGoals(),
                                scene.getObjectHold(),
                                s.simulation.settleTime,
                                s.simulation.heldTolerance,
                                attachment,
                                multi,
                                scene.getController(),
                                s.controller.ikInterval,
                                scene.findJointImpedances()};
}

}  // namespace

GraspApproximation::GraspApproximation(GraspScene& scene, const ApproxOptions& options) {
    system::MultibodyModel& model = scene.updModel();
    const SimTK::MobilizedBody& object = scene.getObject();
    // Critically damped at kBushingFrequency with the object's own mass and central inertia (O is
    // at the centre of mass), per axis: rotation first, as the bushing's axes are ordered.
    const SimTK::MassProperties mp = object.getBody().getDefaultRigidBodyMassProperties();
    const SimTK::Vec3 I = mp.calcCentralInertia().getMoments();
    const SimTK::Vec6 stiffness = calcBushingStiffness(mp, kBushingFrequency);
    const SimTK::Vec6 damping = grasp::calcCriticalDamping(stiffness, I, mp.getMass());
    if (options.attach == ApproxAttach::Multi) {
        // N parts in parallel give the object the same frequency in translation as the bushing.
        const std::vector<grasp::AttachmentSite> sites = findAttachmentSites(scene);
        const double parts = static_cast<double>(sites.size());
        multi_ = std::make_unique<grasp::MultiAttachment>(model.updForces(), object, sites, stiffness / parts,
                                                          damping / parts);
        attachment_ = multi_.get();
    } else if (options.constraint == ApproxConstraint::Weld) {
        if (object.getParentMobilizedBody().getMobilizedBodyIndex() != scene.getPalm().getMobilizedBodyIndex()) {
            throw Error("grasp approximation: the merged weld needs a scene built for it (the object hanging from the palm)");
        }
        weld_ = std::make_unique<grasp::LimitedWeld>(model.updSystem(), model.updMatter(), model.updForces(),
                                                     scene.getPalm(), SimTK::Transform(), object, SimTK::Transform());
        attachment_ = weld_.get();
    } else {
        bushing_ = grasp::LimitedBushing(model.updForces(), scene.getPalm(), SimTK::Transform(), object, SimTK::Transform(),
                                         stiffness, damping);
        attachment_ = &bushing_;
    }
    context_ = std::make_unique<ApproximationContext>(makeContext(scene, *attachment_, multi_.get()));
    switch_ = new GraspSwitch(*context_, model.updForces(), options);
    model.updSystem().addEventHandler(switch_);
    if (SimTK::TriggeredEventHandler* witness = switch_->makeDetachWitness()) model.updSystem().addEventHandler(witness);
    if (SimTK::TriggeredEventHandler* witness = switch_->makeReleaseWitness()) model.updSystem().addEventHandler(witness);
}

}  // namespace graspsim::simulation
