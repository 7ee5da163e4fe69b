#include "validate_command.h"

#include "number_option.h"
#include "output_folder.h"
#include "progress_meter.h"

#include "graspsim/error.h"
#include "graspsim/scenario/scenario_file.h"
#include "graspsim/validation/capacity_comparison.h"
#include "graspsim/validation/plot_script.h"
#include "graspsim/validation/validation_plan.h"
#include "graspsim/validation/validation_report.h"
#include "graspsim/simulation/setup_check.h"

#include <cmath>
#include <iostream>

namespace graspsim::cli {

struct ValidateCommand::Options {
    bool quick = false;
    bool noCapacity = false;  // plain flags: CLI11 prints a negated flag's default into the help ("{false}")
    bool noPlots = false;
    std::vector<std::string> experiments, modes;
    std::string longHold;
    std::string jobs = "1";
    std::string out = "out/validation";
    bool quiet = false;
};

ValidateCommand::ValidateCommand(CLI::App& app) : options_(std::make_shared<Options>()) {
    Options& o = *options_;
    command_ = app.add_subcommand("validate",
                                  "Run the validation suite: full contact vs the approximation for the thesis experiments, "
                                  "with report.md, results.csv, checks.csv and plots");
    command_->add_flag("--quick", o.quick, "the reduced set (ball-clutch, no perturbation, 2 s after settling)");
    command_->add_option("--experiment", o.experiments, "ball-clutch or phone-pinch (repeatable; default both)");
    command_->add_option("--mode", o.modes, "full or an approximation variant, e.g. approx-bushing-merged (repeatable; default all)");
    command_->add_option("--long-hold", o.longHold, "simulated seconds of the long approximation hold (default 600; 0 skips it)");
    command_->add_flag("--no-plots", o.noPlots, "skip the plots (no Python needed)");
    command_->add_flag("--no-capacity", o.noCapacity,
                       "skip the holding-capacity comparison (full contact against each approximation variant, nine loads "
                       "per experiment; without --experiment also the planned scenes against the default; --quick: the -y force only)");
    command_->add_option("--jobs", o.jobs,
                         "capacity ramps run at once, each on its own thread (default 1; the results do not depend on it)");
    command_->add_option("--out", o.out, "output folder (default out/validation)");
    command_->add_flag("-q,--quiet", o.quiet, "no progress display (it appears only on a terminal anyway)");
}

bool ValidateCommand::parsed() const { return command_->parsed(); }

namespace {

// Simulated seconds of a run: the unit of the progress display, since a run's cost grows with it
// (the long hold is 600 s, the others 3 s).
double findSimulatedTime(const validation::ValidationRun& run) {
    return run.options.duration > 0 ? run.options.duration : scenario::findBuiltinScenario(run.scenario).simulation.duration;
}

// Progress over the plan in simulated seconds, shown as "[k/n] run id", moving within each run.
class SuiteProgress {
public:
    SuiteProgress(ProgressMeter& meter, const std::vector<validation::ValidationRun>& runs) : meter_(meter) {
        for (const validation::ValidationRun& run : runs) before_.push_back(total_), total_ += findSimulatedTime(run);
    }
    validation::ValidationProgress makeRunStart() {
        if (!meter_.isShown()) return {};
        return [this](std::size_t index, std::size_t count, const validation::ValidationRun& run) {
            index_ = index;
            detail_ = "[" + std::to_string(index + 1) + "/" + std::to_string(count) + "] " + run.id;
            meter_.update(before_[index], total_, detail_);
        };
    }
    simulation::ProgressCallback makeWithinRun() {
        if (!meter_.isShown()) return {};
        return [this](double t, double) { meter_.update(before_[index_] + t, total_, detail_); };
    }
    void finish() { meter_.update(total_, total_, "done"); }

private:
    ProgressMeter& meter_;
    std::vector<double> before_;  // simulated time before run k (s)
    double total_ = 0;
    std::size_t index_ = 0;
    std::string detail_;
};

}  // namespace

int ValidateCommand::run() const {
    const Options& o = *options_;
    validation::PlanOptions plan{o.quick, o.experiments, o.modes};
    const int jobs = parseCount(o.jobs, "--jobs");
    if (!o.longHold.empty()) {
        plan.longHoldDuration = parseNumber(o.longHold, "--long-hold", "a number of seconds >= 0");
        if (!(plan.longHoldDuration >= 0) || !std::isfinite(plan.longHoldDuration)) {
            throw InputError("--long-hold: value " + o.longHold + " is not accepted; use a number of seconds >= 0");
        }
    }
    const std::vector<validation::ValidationRun> runs = validation::makeValidationPlan(plan);
    // Every run's grasp must be able to start (setup_check.h) before the report folder exists.
    for (const validation::ValidationRun& run : runs) {
        simulation::checkScenarioSetup(scenario::findBuiltinScenario(run.scenario), run.options);
    }
    OutputFolder folder(o.out);  // refused before any simulation if it takes no files; gone again if a run throws
    ProgressMeter meter("validating", o.quiet);
    SuiteProgress progress(meter, runs);
    validation::ValidationResults results =
        validation::runValidation(runs, o.out, progress.makeRunStart(), progress.makeWithinRun());
    progress.finish();
    if (!o.noCapacity) {
        ProgressMeter capacityMeter("capacity", o.quiet);
        validation::CapacityPlan capacityPlan;
        capacityPlan.experiments = o.experiments.empty() && o.quick ? std::vector<std::string>{"ball-clutch"} : o.experiments;
        capacityPlan.variants = o.modes;
        capacityPlan.quick = o.quick;
        capacityPlan.jobs = jobs;
        // The planned scenes with the whole suite only: --experiment names the thesis scenes to run.
        if (o.experiments.empty() && !o.quick) capacityPlan.defaultOnlyExperiments = validation::getPlannedExperiments();
        results.capacity = validation::runCapacityComparison(
            capacityPlan,
            [&](std::size_t index, std::size_t count, const std::string& label) {
                capacityMeter.update(static_cast<double>(index), static_cast<double>(count), label);
            });
        capacityMeter.finish();
    }
    folder.keep();
    meter.finish();
    // The tables first, so that a plotting failure still leaves the numbers.
    validation::writeValidationReport(o.out, results, {});
    std::vector<std::string> plots = !o.noPlots ? validation::runPlotScript(o.out) : std::vector<std::string>{};
    if (!o.noPlots) {
        for (const std::string& p : validation::drawCapacityComparisonPlots(o.out, results.capacity)) plots.push_back(p);
    }
    validation::writeValidationReport(o.out, results, plots);
    std::size_t failed = 0;
    for (const validation::ValidationCheck& c : results.checks) {
        if (c.pass) continue;
        ++failed;
        std::cerr << "FAIL " << c.run << ": " << c.name << " = " << c.value << " " << c.unit << " (bound " << c.relation << " "
                  << c.bound << ")\n";
    }
    std::size_t constantLoads = 0;
    for (const validation::CapacityRow& row : results.capacity) constantLoads += row.overload.method.empty() ? 0 : 1;
    std::cout << "validation: " << results.runs.size() << " runs, " << results.checks.size() << " checks, " << failed
              << " failed, " << results.capacity.size() << " capacity ramps, " << constantLoads << " constant loads, "
              << plots.size() << " plots; report in " << o.out << "/report.md\n";
    return failed == 0 ? 0 : 4;
}

}  // namespace graspsim::cli
