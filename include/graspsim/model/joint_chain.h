#pragma once
/// @file
/// Anatomical joints with several rotational DOF, written as chains of revolute joints.

#include "graspsim/model/model_description.h"

#include <string>
#include <vector>

namespace graspsim::model {

/// One rotational DOF of an anatomical joint.
struct RevoluteSpec {
    std::string name;     ///< joint name, e.g. "index_mcp_flexion"
    Vec3 axis{0, 0, 1};   ///< unit axis in the joint frame (which is the child frame at q = 0)
    double lower = 0;     ///< rad
    double upper = 0;     ///< rad
    double stiffness = 0; ///< passive stiffness toward 0 (N m/rad)
    double damping = 0;   ///< passive damping (N m s/rad)
};

/// Adds `child` to `model`, hanging from `parent` through the revolute joints `dofs` (applied in
/// order, each about the frame the previous one moved). Between two joints sits a massless
/// virtual body named "<child>__<joint>", so the chain is exactly what URDF can express.
/// All joint frames coincide at q = 0 and sit at X_PJ in the parent.
void addRevoluteChain(ModelDescription& model, const std::string& parent, const Transform& X_PJ,
                      const std::vector<RevoluteSpec>& dofs, Body child);

/// Adds `child` welded to `parent` at X_PJ through a fixed joint named "<child>_fixed".
void addFixedBody(ModelDescription& model, const std::string& parent, const Transform& X_PJ, Body child);

}  // namespace graspsim::model
