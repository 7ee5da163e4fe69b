#include "graspsim/validation/validation_plan.h"

#include "graspsim/error.h"
#include "graspsim/scenario/scenario_file.h"

#include <algorithm>

namespace graspsim::validation {

namespace {

std::string joinNames(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& n : names) text += (text.empty() ? "" : ", ") + n;
    return text;
}

void checkKnown(const std::vector<std::string>& given, const std::vector<std::string>& known, const std::string& option) {
    for (const std::string& g : given) {
        if (std::find(known.begin(), known.end(), g) == known.end()) {
            throw InputError(option + ": '" + g + "' is not accepted; use one of " + joinNames(known));
        }
    }
}

// The perturbations to run: none, then the scenario's own, in file order.
std::vector<std::string> findPerturbations(const scenario::Scenario& s, bool quick) {
    std::vector<std::string> names{"none"};
    if (quick) return names;
    for (const scenario::Perturbation& p : s.perturbations) names.push_back(p.name);
    return names;
}

}  // namespace

// Variant names: "full", "full-cvode" (full contact on the CVODE reference integrator at
// kReferenceAccuracy), "full-rigid" (rigid contact), "approx-<constraint>-<attach>".
simulation::SimulationOptions makeVariantOptions(const std::string& variant, const std::string& perturbation, double duration) {
    simulation::SimulationOptions options;
    options.contact = simulation::ContactModel::Compliant;
    const bool full = variant.rfind("full", 0) == 0;
    options.mode = full ? simulation::SimulationMode::Full : simulation::SimulationMode::Approx;
    if (variant == "full-rigid") options.contact = simulation::ContactModel::Rigid;
    if (variant == "full-cvode") {
        options.integrator = simulation::IntegratorChoice::Cvode;
        options.accuracy = kReferenceAccuracy;
    }
    if (variant.find("-weld") != std::string::npos) options.approx.constraint = simulation::ApproxConstraint::Weld;
    if (variant.find("-multi") != std::string::npos) options.approx.attach = simulation::ApproxAttach::Multi;
    // The other limit models and the thesis's box are compared on the thesis's switch (no compliance
    // release), so that each shows its own limits.
    const bool limitVariant = variant.find("-merged-contact") != std::string::npos || variant.find("-merged-compliance") != std::string::npos;
    if (limitVariant || variant.find("-merged-thesis") != std::string::npos) options.approx.releaseTrigger = simulation::ApproxReleaseTrigger::None;
    if (variant.find("-merged-contact") != std::string::npos) options.approx.limitModel = grasp::FrictionLimitModel::ContactGeometry;
    if (variant.find("-merged-compliance") != std::string::npos) options.approx.limitModel = grasp::FrictionLimitModel::Compliance;
    // The default's compliance release on the static model alone, without the creep watch.
    if (variant.find("-merged-static") != std::string::npos) options.approx.releaseCreep = false;
    options.perturbation = perturbation;
    options.duration = duration;
    return options;
}

const std::vector<std::string>& getThesisExperiments() {
    static const std::vector<std::string> names{"ball-clutch", "phone-pinch"};
    return names;
}

const std::vector<std::string>& getPlannedExperiments() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> planned;
        for (const std::string& name : scenario::getBuiltinScenarioNames()) {
            const std::vector<std::string>& thesis = getThesisExperiments();
            if (std::find(thesis.begin(), thesis.end(), name) == thesis.end()) planned.push_back(name);
        }
        return planned;
    }();
    return names;
}

const std::vector<std::string>& getAvailableVariants() {
    static const std::vector<std::string> names{"full", "full-cvode", "full-rigid", "approx-bushing-merged", "approx-weld-merged",
                                                "approx-bushing-multi"};
    return names;
}

std::vector<ValidationRun> makeValidationPlan(const PlanOptions& options) {
    checkKnown(options.experiments, getThesisExperiments(), "--experiment");
    checkKnown(options.variants, getAvailableVariants(), "--mode");
    std::vector<std::string> experiments = options.experiments.empty() ? getThesisExperiments() : options.experiments;
    if (options.quick && options.experiments.empty()) experiments = {"ball-clutch"};
    std::vector<std::string> variants = options.variants.empty() ? getAvailableVariants() : options.variants;
    // Rigid contact steps at 1e-4 s (about 20 s of CPU per simulated second): not in the quick set
    // unless asked for; ctest runs the rigid-vs-compliant verdicts in contact_model_agreement_test.
    if (options.quick && options.variants.empty()) variants.erase(std::find(variants.begin(), variants.end(), "full-rigid"));
    std::vector<ValidationRun> runs;
    for (const std::string& experiment : experiments) {
        const scenario::Scenario s = scenario::findBuiltinScenario(experiment);
        // Quick: 2 s after settling, the window of the approximation's 2-mm/2-degree bound.
        const double duration = options.quick ? s.simulation.settleTime + 2.0 : s.simulation.duration;
        for (const std::string& perturbation : findPerturbations(s, options.quick)) {
            const std::string stem = experiment + "_" + perturbation + "_";
            // Every comparison needs its full-contact reference, whether or not "full" was asked for.
            runs.push_back({stem + "full", experiment, "full", makeVariantOptions("full", perturbation, duration), ""});
            for (const std::string& variant : variants) {
                if (variant == "full") continue;
                // The integrator reference once per experiment: without perturbation.
                if (variant == "full-cvode" && perturbation != "none") continue;
                // Rigid contact compares with compliant contact: the same stem's "full".
                runs.push_back({stem + variant, experiment, variant, makeVariantOptions(variant, perturbation, duration), stem + "full"});
            }
        }
    }
    const auto approx = std::find_if(variants.begin(), variants.end(), [](const std::string& v) { return v.rfind("approx", 0) == 0; });
    if (!options.quick && options.longHoldDuration > 0 && approx != variants.end()) {
        const std::string experiment = experiments.front();
        ValidationRun hold{experiment + "_none_" + *approx + "_long-hold", experiment, *approx,
                           makeVariantOptions(*approx, "none", options.longHoldDuration), "", true};
        runs.push_back(hold);
    }
    return runs;
}

}  // namespace graspsim::validation
