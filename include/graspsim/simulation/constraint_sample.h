#pragma once
/// @file
/// The approximation's palm-object constraint at one output time (constraint.csv): where it acts,
/// its limits and the reaction it carries, so that a reader can see how close to slipping the
/// engaged grasp is.

#include "graspsim/simbody.h"

#include <optional>

namespace graspsim::simulation {

struct ApproximationContext;

/// The merged approximation's constraint (bushing or weld) while engaged.
/// Axes k in SpatialVec order: 0-2 rotation about the constraint frame M's x, y, z, 3-5
/// translation along them (grasp/limited_bushing.h, grasp/limited_weld.h).
struct ConstraintSample {
    double time = 0;              ///< s
    SimTK::Transform X_GM;        ///< pose of the constraint frame M (on the object) in ground (m)
    /// limits in force (N m for 0-2, N for 3-5); +Infinity on locked axes. For two-sided limits
    /// (--limits compliance) the upper sides: the reaction stays <= limits.
    SimTK::Vec6 limits{0};
    /// The lower sides (the reaction stays >= -lowerLimits); equal to `limits` for symmetric ones.
    SimTK::Vec6 lowerLimits{0};
    SimTK::Vec6 reaction{0};      ///< generalized reaction on the object along M's axes (N m, N)
    SimTK::SpatialVec wrench_G;   ///< the same as a spatial force on the object (moment about M's origin, N m; force, N), in ground
};

/// The sample at `state` when the merged approximation of `context` is engaged there; nullopt
/// with the multi attachment (one element per fingertip, no single constraint), or while not
/// engaged. Realizes `state` to the attachment's reaction stage when engaged
/// (grasp::GraspAttachment::getReactionStage: the weld's reaction is its multipliers).
std::optional<ConstraintSample> findConstraintSample(const ApproximationContext& context, const SimTK::State& state);

}  // namespace graspsim::simulation
