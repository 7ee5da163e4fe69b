#pragma once
/// @file
/// A run's motion and contact forces in OpenSim's storage formats, beside the CSV files.
///
/// - motion.mot: OpenSim's motion file (Storage format, version 1): a header of name line,
///   `version=1`, `nRows=`, `nColumns=` (time included), `inDegrees=yes`, `endheader`, then a
///   tab-separated table `time` and one column per hand joint angle in degrees, labelled with the
///   coordinate names of the exported .osim (osim_model.h: the joint names).
/// - object_forces.sto: the same header with `inDegrees=no`; per contact c (a finger geometry
///   against an object geometry; label `<hand body>_<hand shape>`, `_2`, `_3`... when one pair
///   touches at several points) the force the finger applies to the object, `c_on_object_vx/vy/vz`
///   (N, ground), the reaction on the hand body, `c_on_hand_vx/vy/vz` (N, ground), and the contact
///   point `c_px/py/pz` (m, ground). A contact that is not touching at a time has zero force and
///   keeps its last point (its first while it has none yet).
/// - external_loads.xml: an OpenSim `ExternalLoads` with one `ExternalForce` per contact, applying
///   `c_on_hand_v*` at `c_p*` (both in ground) to the hand body, reading object_forces.sto.
/// Numbers are written with 17 significant digits.

#include "graspsim/simulation/grasp_simulation.h"

#include <string>

namespace graspsim::opensim {

/// motion.mot's text (every hand joint of graspsim is a hinge: all columns are in degrees).
std::string formatMotionMot(const simulation::SimulationResult& result);

/// object_forces.sto's text.
std::string formatObjectForcesSto(const simulation::SimulationResult& result);

/// external_loads.xml's text, referring to `dataFile` (object_forces.sto) by name.
std::string formatExternalLoadsXml(const simulation::SimulationResult& result, const std::string& dataFile);

/// Writes motion.mot, object_forces.sto and external_loads.xml into `folder`, which must exist.
/// @throws graspsim::InputError naming the file when it cannot be written.
void writeOpenSimResultFiles(const std::string& folder, const simulation::SimulationResult& result);

}  // namespace graspsim::opensim
