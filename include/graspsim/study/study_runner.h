#pragma once
/// @file
/// Running a study's cases (all, or one shard) on N local processes, each case a
/// `graspsim simulate` child whose outputs are committed to its case folder at once
/// (study_folder.h). Finished cases are skipped, so a killed run restarted picks up where it
/// stopped; a case that fails is recorded with its error and the others go on.

#include "graspsim/scenario/scenario_file.h"
#include "graspsim/study/study_case.h"
#include "graspsim/study/study_spec.h"

#include <functional>
#include <string>

namespace graspsim::study {

/// Where a run stands, reported after each finished case and once at the start.
struct RunProgress {
    int finished = 0;       ///< cases of this run's shard finished (including skipped ones)
    int total = 0;          ///< cases in this run's shard
    int incomplete = 0;     ///< of the finished ones, those stopped early (CaseStatus::Incomplete)
    int failed = 0;         ///< of the finished ones, those without a result (CaseStatus::Failed)
    double elapsed = 0;     ///< wall seconds since the run started
    double remaining = -1;  ///< estimated wall seconds left; -1 until one case ran
};

/// How to run.
struct RunSettings {
    std::string folder;      ///< the study's output folder, prepared (prepareStudyFolder)
    int jobs = 1;            ///< child processes at once, >= 1
    Shard shard;             ///< which cases; 0/1 = all
    bool retryFailed = false;  ///< run failed and incomplete cases again instead of keeping them
    std::string executable;  ///< the graspsim binary that runs `simulate` for each case
    std::function<void(const RunProgress&)> progress;  ///< may be empty
};

/// What a run did.
struct RunReport {
    int total = 0;    ///< cases in the shard
    int skipped = 0;  ///< already finished before this run
    int ran = 0;      ///< run now
    int incomplete = 0;  ///< of all the shard's cases, those stopped early (CaseStatus::Incomplete)
    int failed = 0;   ///< of all the shard's cases, those without a result (CaseStatus::Failed)
};

/// The progress line a terminal shows: a bar, the cases finished, the incomplete and failed ones
/// counted apart as the summary counts them (formatFailureCounts), elapsed time and the time left
/// ("[###############...............] 2/4 cases, 1 incomplete, 0 failed, 0:00:12 elapsed, ETA 0:00:12").
std::string formatRunProgress(const RunProgress& progress);

/// Runs every unfinished case of the shard.
/// @throws graspsim::Error when a child process cannot be started or a case folder cannot be written.
RunReport runStudyCases(const StudySpec& spec, const std::vector<scenario::ScenarioText>& bases, const RunSettings& settings);

}  // namespace graspsim::study
