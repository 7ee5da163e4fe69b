#pragma once
/// @file
/// The thesis's model (Guerroudj 2022, section 5.1): every finger segment 20 g (the thumb's
/// metacarpal counts as a finger segment, so 15 segments), palm 250 g, each arm 5.45 kg in total.

#include "graspsim/model/model_description.h"

namespace graspsim::model {

/// Mass of every phalanx (and thumb metacarpal) in the thesis model (kg).
constexpr double kThesisFingerSegmentMass = 0.020;
/// Mass of the palm in the thesis model (kg).
constexpr double kThesisPalmMass = 0.250;
/// Total mass of one arm (upper arm + forearm + hand) in the thesis model (kg).
constexpr double kThesisArmMass = 5.45;

/// Overrides the masses of every arm in `model` with the thesis's values. Each body keeps its
/// shape: centre of mass unchanged, inertia scaled by the mass ratio. Upper arm and forearm share
/// what is left of 5.45 kg in their de Leva proportion.
void applyThesisPreset(ModelDescription& model);

}  // namespace graspsim::model
