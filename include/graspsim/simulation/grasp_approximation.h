#pragma once
/// @file
/// The approximation of `--mode approx` built on top of a scene (docs/design.md, "The
/// approximation on top of the scene"): the grasp switch (grasp_switch.h; with
/// ApproxAttach::Multi also its detach witness) added to the scene's system, given at
/// construction everything it uses (ApproximationContext) and options already resolved
/// (resolveApproxOptions). The scene knows nothing of it.
///
/// The friction-limited attachment itself (bushing, weld or multi-attachment) is a Simbody
/// element of the scene (GraspScene::getAttachment()): Simbody sums the forces in the order they
/// were added, so an attachment added after the scene's loads would change the object's
/// accelerations by round-off, and every approx-mode output with it.

#include "graspsim/simulation/approximation_context.h"
#include "graspsim/simulation/grasp_scene.h"
#include "graspsim/simulation/grasp_switch.h"
#include "graspsim/simulation/simulation_options.h"

namespace graspsim::simulation {

/// See the file comment. Neither copyable nor movable: the switch refers to its context.
class GraspApproximation {
public:
    /// Adds the switch to `scene`'s system and realizes the system's topology again; call before
    /// the scene's first state is made (GraspScene::makeInitialState()).
    /// @param scene an approx-mode scene (GraspScene::getAttachment() set).
    /// @param options resolved with resolveApproxOptions().
    /// @throws graspsim::Error when `scene` is not an approx-mode scene.
    GraspApproximation(GraspScene& scene, const ApproxOptions& options);
    GraspApproximation(const GraspApproximation&) = delete;
    GraspApproximation& operator=(const GraspApproximation&) = delete;

    /// The grasp switch (owned by the scene's System, as Simbody owns event handlers).
    const GraspSwitch& getSwitch() const { return *switch_; }
    const ApproximationContext& getContext() const { return context_; }

private:
    ApproximationContext context_;
    GraspSwitch* switch_ = nullptr;
};

}  // namespace graspsim::simulation
