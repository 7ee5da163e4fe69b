#pragma once
/// @file
/// The study's results table, merged from its case folders (whichever process or Slurm task
/// ran them): results.csv with one row per case in case order,
///
///     case, <each axis>, status, <each measure>, error
///
/// values as the study file or the sampling wrote them, measures as summary.json has them
/// (true/false, numbers in JSON's shortest round-trip form, empty when the run has no such
/// key or did not finish), status ok | incomplete | failed | missing, and the error in quotes.

#include "graspsim/study/study_spec.h"

#include <string>
#include <vector>

namespace graspsim::study {

/// What the merge found.
struct StudyTable {
    std::string csv;              ///< results.csv's text
    int total = 0;                ///< cases in the study
    std::vector<int> missing;     ///< case numbers not finished (never run, or killed)
    std::vector<int> incomplete;  ///< finished, status incomplete (stopped early)
    std::vector<int> failed;      ///< finished, status failed (no result)
};

/// Reads every case folder of the study in `folder` into the table.
/// @throws graspsim::InputError when a finished case's files cannot be read.
StudyTable collectStudyTable(const StudySpec& spec, const std::string& folder);

/// Writes `table.csv` to `folder`/results.csv (atomically).
void writeStudyTable(const std::string& folder, const StudyTable& table);

/// The cases that are not ok in the status column's words: "2 incomplete, 1 failed", or "1 failed"
/// when none is incomplete (so a study without any reads as it always did). The summary, the
/// progress line and a shard's line all count them so.
std::string formatFailureCounts(std::size_t incomplete, std::size_t failed);

/// "3, 7, 12" (at most `limit` numbers, then "... (N in all)").
std::string formatCaseList(const std::vector<int>& cases, std::size_t limit = 20);

}  // namespace graspsim::study
