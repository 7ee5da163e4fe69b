#pragma once
/// @file
/// A study's output folder:
///
///     DIR/study.json          which study this folder belongs to (name, fingerprint, source)
///     DIR/study.yaml          a copy of the study file
///     DIR/cases/0007/         one folder per finished case: scenario.yaml, the run's files
///                             (summary.json, trajectory.csv, ...), stdout.txt, stderr.txt,
///                             case.json
///     DIR/results.csv         one row per case (study run without --shard, study collect)
///     DIR/plots/*.png         each measure against each axis
///
/// A case is run in DIR/cases/0007.tmp-\<pid\> and renamed to DIR/cases/0007 once its case.json
/// is written, so a case folder exists only complete; a killed run leaves temporaries, which
/// the next run of that case removes.

#include "graspsim/study/study_spec.h"

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace graspsim::study {

/// How one case ended.
enum class CaseStatus {
    Ok,          ///< the simulation ran to its end
    Incomplete,  ///< it stopped early (diverged); summary.json says why
    Failed       ///< no result: parameters not accepted, or the process failed
};

/// "ok", "incomplete", "failed".
std::string toString(CaseStatus status);

/// The contents of a finished case's case.json.
struct CaseRecord {
    int index = 0;
    CaseStatus status = CaseStatus::Failed;
    std::string error;                ///< one line; empty when Ok
    std::vector<std::string> values;  ///< the axis values, as in StudyCase
};

/// A fingerprint of the study: its file text and its base scenario's text (FNV-1a, hex).
std::string calcStudyFingerprint(const StudySpec& spec, const std::string& baseText);

/// Makes `folder` this study's output folder, or checks that it already is.
/// @throws graspsim::InputError when it holds another study's results or other files, or
/// cannot be created; nothing is written then.
void prepareStudyFolder(const std::string& folder, const StudySpec& spec, const std::string& baseText);

/// Reads the study a prepared folder belongs to (its study.yaml, read as from its original path).
/// @throws graspsim::InputError when `folder` is not a study folder.
StudySpec loadFolderStudy(const std::string& folder);

/// DIR/cases/0007: where case `index` is kept once finished.
std::string findCaseFolder(const std::string& folder, int index);

/// True when case `index` has finished (its folder and case.json exist).
bool isCaseFinished(const std::string& folder, int index);

/// Removes what killed runs of case `index` left behind (its .tmp-* folders).
void removeCaseTemporaries(const std::string& folder, int index);

/// Writes `record` into `tmpFolder`/case.json, then renames `tmpFolder` to the case's folder.
/// What the case's process printed (stdout.txt, stderr.txt) and the record's error name the
/// case's folder wherever they named `tmpFolder` ("files in DIR/cases/0007").
/// @throws graspsim::InputError when the folder cannot be written or renamed.
void commitCase(const std::string& folder, const std::string& tmpFolder, const CaseRecord& record);

/// The record of finished case `index`.
/// @throws graspsim::InputError when its case.json is missing or cannot be read.
CaseRecord readCaseRecord(const std::string& folder, int index);

/// The measures of case `index`: the summary.json `graspsim simulate` wrote, or for a capacity
/// study the one measurement of the capacity.json `graspsim capacity` wrote (its "failure" key
/// says why a run stopped early); an empty object when the case wrote none (it failed before).
/// @throws graspsim::InputError when the file is not readable JSON.
nlohmann::json readCaseSummary(const std::string& folder, int index, StudyCommand command = StudyCommand::Simulate);

}  // namespace graspsim::study
