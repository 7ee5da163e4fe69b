#pragma once
/// @file
/// The lateral pinch (Feix et al. 2016 'lateral pinch'): the thumb pad presses a thin object (a
/// card, a key) against the radial side of the index finger's middle phalanx.
///
/// Its second contact is no fingertip pad, so the plan adds an end-effector to the model: a point
/// on the radial surface of the index's middle phalanx (model::SegmentPoint, written into the
/// planned scenario's `end_effectors:`). The controller's IK places it like a fingertip, moving the
/// joints from the palm out to that phalanx (index MCP abduction and flexion, PIP); contact is the
/// phalanx's capsule against the object, as for any segment.

#include "graspsim/model/build_options.h"
#include "graspsim/planning/grasp_template.h"

namespace graspsim::planning {

/// Name of the lateral pinch's index end-effector.
inline constexpr const char* kIndexRadialEffector = "index_middle_radial";

/// The point on the radial side (+z of the hand, toward the thumb) of the index's middle phalanx,
/// halfway along its capsule, on its surface; in the phalanx's body frame (m), rounded to 0.1 mm.
/// @throws graspsim::InputError if the model of `options` has no capsule on "index_middle".
model::SegmentPoint findIndexRadialPoint(const model::BuildOptions& options);

/// `options` with the index radial point among its segment points (unchanged if it is there).
model::BuildOptions addIndexRadialPoint(model::BuildOptions options);

/// The lateral pinch's template: the phone pinch's arm posture (thumb up), the index flexed, the
/// other fingers curled into the palm, the thumb adducted over the index; goals on the thumb pad
/// and the index's radial side.
GraspTemplate findLateralTemplate();

}  // namespace graspsim::planning
