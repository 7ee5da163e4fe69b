#include "graspsim/scenario/scenario.h"

#include "graspsim/anthropometry/subject.h"

namespace graspsim::scenario {

const Perturbation* Scenario::findPerturbation(const std::string& perturbationName) const {
    for (const Perturbation& perturbation : perturbations) {
        if (perturbation.name == perturbationName) return &perturbation;
    }
    return nullptr;
}

model::BuildOptions Scenario::makeDefaultBodyOptions() {
    model::BuildOptions options;
    options.body = model::BodyKind::Arm;
    options.preset = model::Preset::Thesis;
    options.subject = anthropometry::getReferenceSubject(anthropometry::Sex::Male);
    return options;
}

}  // namespace graspsim::scenario
