#pragma once
/// @file
/// The approximation of `--mode approx` built on top of a scene (docs/design.md, "The
/// approximation on top of the scene"): the friction-limited attachment chosen by ApproxOptions
/// (a grasp::LimitedBushing or grasp::LimitedWeld palm-object, or a grasp::MultiAttachment; every
/// one through the grasp::GraspAttachment interface) and the grasp switch (grasp_switch.h; with
/// ApproxAttach::Multi also its detach witness), given at construction everything they use
/// (ApproximationContext) and options already resolved (resolveApproxOptions). The scene knows
/// nothing of it.
///
/// The attachment's parts are Simbody elements added to the scene's system: a bushing is
/// critically damped at kBushingFrequency with the object's own mass and inertia (the grasp switch
/// stiffens it at engagement from its friction limits), the weld has no stiffness to choose, and
/// the multi-attachment has one part per goal, at the goal on the surface, sharing the bushing's
/// stiffness.

#include "graspsim/grasp/limited_bushing.h"
#include "graspsim/grasp/limited_weld.h"
#include "graspsim/grasp/multi_attachment.h"
#include "graspsim/simulation/approximation_context.h"
#include "graspsim/simulation/grasp_scene.h"
#include "graspsim/simulation/grasp_switch.h"
#include "graspsim/simulation/simulation_options.h"

#include "graspsim/simbody.h"

#include <memory>

namespace graspsim::simulation {

/// Natural frequency of the approximation's bushing with the object's own mass and inertia
/// (rad/s, critically damped): stiff enough that gravity sags the object by g / w^2 = 0.25 mm,
/// soft enough to leave the integrator steps of the full-contact run (about 5 ms period).
/// The default only: the grasp switch stiffens the merged bushing at engagement from its friction
/// limits (ApproxOptions::maxEngagedPenetration).
constexpr double kBushingFrequency = 200.0;

/// See the file comment. Neither copyable nor movable: the switch refers to its context.
class GraspApproximation {
public:
    /// Adds the attachment and the switch to `scene`'s system; the caller realizes the topology
    /// afterwards (GraspExperiment does, after the loads).
    /// @param scene a scene built for SimulationMode::Approx with the same ApproxOptions::constraint
    ///        and attach (the merged weld needs the object hanging from the palm).
    /// @param options resolved with resolveApproxOptions().
    GraspApproximation(GraspScene& scene, const ApproxOptions& options);
    GraspApproximation(const GraspApproximation&) = delete;
    GraspApproximation& operator=(const GraspApproximation&) = delete;

    /// The attachment, whichever realizes it.
    const grasp::GraspAttachment& getAttachment() const { return *attachment_; }
    /// The grasp switch (owned by the scene's System, as Simbody owns event handlers).
    const GraspSwitch& getSwitch() const { return *switch_; }
    const ApproximationContext& getContext() const { return *context_; }
    /// Lets the switch's compliance trigger see the run's external loads (GraspSwitch::setObjectLoads).
    void setObjectLoads(const ObjectLoads& loads) { switch_->setObjectLoads(loads); }

private:
    grasp::LimitedBushing bushing_;
    std::unique_ptr<grasp::MultiAttachment> multi_;
    std::unique_ptr<grasp::LimitedWeld> weld_;  // its event handlers refer to it
    const grasp::GraspAttachment* attachment_ = nullptr;  // one of bushing_, *weld_, *multi_
    std::unique_ptr<ApproximationContext> context_;
    GraspSwitch* switch_ = nullptr;
};

}  // namespace graspsim::simulation
