#include "bench_command.h"

#include "number_option.h"
#include "progress_meter.h"

#include "graspsim/error.h"
#include "graspsim/validation/cost_table.h"

#include <cmath>
#include <iostream>

namespace graspsim::cli {

struct BenchCommand::Options {
    bool json = false;
    std::string duration;
    bool quiet = false;
};

BenchCommand::BenchCommand(CLI::App& app) : options_(std::make_shared<Options>()) {
    Options& o = *options_;
    command_ = app.add_subcommand("bench", "Measure the thesis's Table 5.1 on this machine: full contact (per stepper) vs the approximation and the floor");
    command_->add_flag("--json", o.json, "print JSON instead of the table");
    command_->add_option("--duration", o.duration, "simulated seconds per run, >= 1.5 (default 2)");
    command_->add_flag("-q,--quiet", o.quiet, "no progress display (it appears only on a terminal anyway)");
}

bool BenchCommand::parsed() const { return command_->parsed(); }

int BenchCommand::run() const {
    const Options& o = *options_;
    double duration = 2.0;
    if (!o.duration.empty()) {
        duration = parseNumber(o.duration, "--duration", "a number of seconds >= 1.5");
        // The approximation engages once the grasp has settled (1 s) and needs time engaged.
        if (!(duration >= 1.5) || !std::isfinite(duration)) {
            throw InputError("--duration: value " + o.duration + " is not accepted; use a number of seconds >= 1.5");
        }
    }
    ProgressMeter meter("benchmarking", o.quiet);
    validation::CostProgress progress;
    if (meter.isShown()) {
        progress = [&meter](std::size_t done, std::size_t total, const std::string& what) {
            meter.update(static_cast<double>(done), static_cast<double>(total), what);
        };
    }
    const validation::CostTable table = validation::measureCostTable(duration, 400, progress);
    meter.finish();
    std::cout << (o.json ? validation::formatCostTableJson(table) : validation::formatCostTable(table));
    return 0;
}

}  // namespace graspsim::cli
