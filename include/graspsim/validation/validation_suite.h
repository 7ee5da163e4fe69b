#pragma once
/// @file
/// Running `graspsim validate`: every planned simulation, its comparison with full contact, the
/// bounds, and the files it leaves in the output folder.
///
/// `DIR/runs/<run id>/` holds each run's own files (trajectory.csv, contacts.csv, summary.json,
/// events.csv; see result_files.h); DIR/results.csv one row per run; DIR/checks.csv one row per
/// bound; DIR/report.md the tables for people (validation_report.h).

#include "graspsim/simulation/grasp_simulation.h"
#include "graspsim/validation/capacity_comparison.h"
#include "graspsim/validation/validation_checks.h"

#include <functional>
#include <string>
#include <vector>

namespace graspsim::validation {

/// Everything the suite measured.
struct ValidationResults {
    std::vector<RunRecord> runs;          ///< in plan order
    std::vector<ValidationCheck> checks;  ///< in plan order
    std::vector<CapacityRow> capacity;    ///< the capacity comparison (empty when not run)
    double wallTime = 0;                  ///< s, the whole suite
    /// True when every check passed.
    bool passed() const;
};

/// Called before each run with its index (from 0), the number of runs and the run.
using ValidationProgress = std::function<void(std::size_t index, std::size_t count, const ValidationRun& run)>;

/// Runs `plan` (from makeValidationPlan()), then the analytic cases (analytic_cases.h), and
/// writes every run's files (a complete result folder each, results/result_folder.h) under
/// `folder`/runs. The folder must exist and be writable. A run that stops early is kept (its checks fail).
/// `progress` is told before each run, `runProgress` within it (simulation::ProgressCallback).
/// @throws graspsim::InputError when a file cannot be written.
ValidationResults runValidation(const std::vector<ValidationRun>& plan, const std::string& folder,
                                const ValidationProgress& progress = {},
                                const simulation::ProgressCallback& runProgress = {});

}  // namespace graspsim::validation
