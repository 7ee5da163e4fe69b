#pragma once
// How one description body becomes a Simbody mobilized body: its mass properties and the
// mobilizer of the joint that connects it to its parent. Private to the system layer.

#include <simbody/Simbody.h>

#include <string>

#include "graspsim/model/model_description.h"
#include "graspsim/system/simtk_conversion.h"

namespace graspsim::system {

/// Mass properties about the body origin, as SimTK::MassProperties wants them: mass (kg),
/// p_BCm (m) and the central inertia shifted to the body origin (kg m^2), all in B.
SimTK::MassProperties calcMassPropertiesAboutOrigin(const model::Body& body);

/// Rotation R_JF of a mobilizer frame F whose `mobilizerAxis` (z for a pin, x for a slider)
/// lies along `axis_J`, the joint axis in the joint frame J.
SimTK::Rotation calcAxisAlignedRotation(const model::Vec3& axis_J,
                                        SimTK::CoordinateAxis mobilizerAxis);

/// Welds the root body to Ground at X_GR.
SimTK::MobilizedBody addRootMobilizedBody(SimTK::SimbodyMatterSubsystem& matter,
                                          const model::Body& root, const model::Transform& X_GR);

/// Adds `child` to `parent` through `joint`: a Pin (Revolute, Continuous), Slider (Prismatic)
/// or Weld (Fixed) whose frames are chosen so that the child frame B coincides with the joint
/// frame J at q = 0 and moves about or along the joint axis: X_PB(q) = X_PJ * X_JB(q).
SimTK::MobilizedBody addJointMobilizedBody(SimTK::MobilizedBody& parent, const model::Joint& joint,
                                           const model::Body& child);

}  // namespace graspsim::system
