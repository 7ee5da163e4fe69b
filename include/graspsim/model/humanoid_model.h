#pragma once
/// @file
/// A whole-body humanoid from every de Leva (1996) segment, with both arms and hands.
///
/// Tree: pelvis (de Leva lower trunk, root, welded to ground with the mid-hip point at the
/// origin) -> middle trunk (lumbar 3 DOF at OMPH) -> upper trunk (thoracic 3 DOF at XYPH) ->
/// head (neck 3 DOF at SUPR); arms (27 DOF each, see arm_model.h) at the shoulders of the upper
/// trunk; legs at the hips: thigh (hip 3), shank (knee 1), foot (ankle 2). 75 DOF in all.
/// Names carry "r_" and "l_" side prefixes; the left side is the mirror image of the right
/// (positions z -> -z, rotation axes (x, y, z) -> (-x, -y, z)), so equal joint angles give
/// mirror-image poses. Joint positions that de Leva does not give (shoulder and hip widths)
/// come from anthropometry/body_proportions.csv.

#include "graspsim/model/build_options.h"
#include "graspsim/model/model_description.h"

namespace graspsim::model {

/// Builds the humanoid for options.subject with options' passive joint parameters.
ModelDescription buildHumanoidModel(const BuildOptions& options);

}  // namespace graspsim::model
