#include "graspsim/validation/validation_suite.h"

#include "graspsim/error.h"
#include "graspsim/results/result_folder.h"
#include "graspsim/validation/analytic_cases.h"
#include "graspsim/scenario/scenario_file.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>

namespace graspsim::validation {

bool ValidationResults::passed() const {
    return std::all_of(checks.begin(), checks.end(), [](const ValidationCheck& c) { return c.pass; });
}

namespace {

std::string formatNumber(double value) {
    // The shortest of 15 or 17 significant digits that reads back to the same double.
    char text[32];
    std::snprintf(text, sizeof text, "%.15g", value);
    if (std::strtod(text, nullptr) != value) std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

// Each run's folder is a complete result (viewable with graspsim view); its provenance names the
// run of the suite, as the suite's command line is not known here.
void writeRunFiles(const std::string& folder, const ValidationRun& run, const scenario::Scenario& scenario,
                   const simulation::SimulationResult& result) {
    const std::filesystem::path dir = std::filesystem::path(folder) / "runs" / run.id;
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw InputError(dir.string() + ": cannot be created (" + ec.message() + ")");
    results::RunProvenance provenance;
    provenance.run = {{"validation_run", run.id}, {"variant", run.variant}, {"perturbation", run.options.perturbation},
                      {"sim_time_s", formatNumber(result.summary.simTime)}};
    results::writeResultFolder(dir.string(), scenario, result, provenance);
}

}  // namespace

ValidationResults runValidation(const std::vector<ValidationRun>& plan, const std::string& folder,
                                const ValidationProgress& progress, const simulation::ProgressCallback& runProgress) {
    const auto start = std::chrono::steady_clock::now();
    ValidationResults results;
    // Full-contact results are kept only until the runs compared with them are done.
    std::map<std::string, simulation::SimulationResult> references;
    for (std::size_t k = 0; k < plan.size(); ++k) {
        const ValidationRun& run = plan[k];
        if (progress) progress(k, plan.size(), run);
        const scenario::Scenario s = scenario::findBuiltinScenario(run.scenario);
        simulation::SimulationResult result = simulation::runGraspSimulation(s, run.options, runProgress);
        writeRunFiles(folder, run, s, result);
        RunRecord record;
        record.run = run;
        record.summary = result.summary;
        record.slipOnset = findSlipOnset(result.trajectory, result.summary.settleTime, kSlipDistance);
        const auto reference = references.find(run.reference);
        if (reference != references.end()) compareWithReference(reference->second, result, record);
        for (ValidationCheck& c : checkRun(record)) results.checks.push_back(std::move(c));
        results.runs.push_back(std::move(record));
        if (run.reference.empty() && !run.longHold) references[run.id] = std::move(result);
    }
    for (ValidationCheck& c : runAnalyticCases()) results.checks.push_back(std::move(c));
    results.wallTime = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return results;
}

}  // namespace graspsim::validation
