#pragma once
/// @file
/// A whole result folder: the run's output files (result_files.h) and what made them: the resolved
/// scenario (scenario.yaml, every field written out), the arm and hand model it built (model.urdf)
/// and provenance.json (provenance.h). Every file is written whole under a temporary name and
/// renamed; provenance.json comes last, so a folder that has it is complete.

#include "graspsim/results/provenance.h"
#include "graspsim/scenario/scenario.h"
#include "graspsim/simulation/grasp_simulation.h"

#include <string>

namespace graspsim::results {

/// Writes every file of a result into `folder`, which must exist.
/// @throws graspsim::InputError naming the file when one cannot be written.
void writeResultFolder(const std::string& folder, const scenario::Scenario& scenario,
                       const simulation::SimulationResult& result, const RunProvenance& run);

}  // namespace graspsim::results
