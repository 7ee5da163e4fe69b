#pragma once
// What URDF cannot say, in namespaced elements under <robot> that other URDF readers skip
// (urdfdom reads only <link>, <joint> and <material> children of <robot>):
//
//   <robot name="..." xmlns:graspsim="https://graspsim.invalid/urdf-extensions">
//     <graspsim:link name="palm" segment="hand"/>
//     <graspsim:joint name="index_mcp_flex" stiffness="0.25" rest_angle="0.1"/>
//     <graspsim:end_effector name="index_tip" link="index_distal" xyz="0 0 0.02"/>

#include "urdf_source.h"

#include "graspsim/model/model_description.h"

class TiXmlElement;

namespace graspsim::model {

/// The namespace the extension elements belong to (a name only; nothing is fetched from it).
inline constexpr const char* kGraspsimNamespaceUri = "https://graspsim.invalid/urdf-extensions";

/// The prefix graspsim writes, and reads when <robot> binds no prefix to kGraspsimNamespaceUri.
inline constexpr const char* kGraspsimPrefix = "graspsim";

/// Appends one <graspsim:link> per body with a segment, one <graspsim:joint> per joint with a
/// non-zero stiffness or rest angle, and one <graspsim:end_effector> per end-effector.
void appendGraspsimExtensions(const ModelDescription& model, TiXmlElement& robot);

/// Reads the extension elements of `robot` into `model`, whose bodies and joints are already read.
/// @throws graspsim::InputError for an unknown extension element or attribute, a name that is
///   not a link or joint of the file, a repeated entry, or a value that is not a finite number
///   (stiffness must also be >= 0).
void applyGraspsimExtensions(const TiXmlElement& robot, const UrdfSource& source, ModelDescription& model);

}  // namespace graspsim::model
