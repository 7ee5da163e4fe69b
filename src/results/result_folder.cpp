#include "graspsim/results/result_folder.h"

#include "graspsim/io/atomic_file.h"
#include "graspsim/model/body_model.h"
#include "graspsim/model/urdf_export.h"
#include "graspsim/results/result_files.h"
#include "graspsim/scenario/scenario_writer.h"

namespace graspsim::results {

void writeResultFolder(const std::string& folder, const scenario::Scenario& scenario,
                       const simulation::SimulationResult& result, const RunProvenance& run) {
    const std::string header = "The scenario of this run, resolved: every field written out, defaults included.\n"
                               "Read back by graspsim like any scenario file (angles in degrees).";
    io::writeFileAtomically(folder + "/scenario.yaml", scenario::formatScenarioYaml(scenario, header));
    io::writeFileAtomically(folder + "/model.urdf", model::writeUrdf(model::buildBodyModel(scenario.bodyOptions)));
    writeResultFiles(folder, result);
    io::writeFileAtomically(folder + "/provenance.json", formatProvenanceJson(findBuildProvenance(), run));
}

}  // namespace graspsim::results
