#pragma once
/// @file
/// What one case runs: the base scenario with the case's field values written in, and the
/// `graspsim simulate` (or `graspsim capacity`) options it sets.
///
/// A field value is written into the base scenario's YAML at its dotted path (sections missing
/// on the way are added), and the result is parsed by the scenario reader: a field that does not
/// exist or a value it does not accept gets the reader's own message.

#include "graspsim/scenario/scenario_file.h"
#include "graspsim/study/study_case.h"
#include "graspsim/study/study_spec.h"

#include <string>
#include <utility>
#include <vector>

namespace graspsim::study {

/// One case, ready to run.
struct CaseSetup {
    std::string scenarioYaml;  ///< the case's scenario file text (checked by the reader)
    /// The command's options, e.g. {"--mode", "approx"}, in getRunOptionNames order; a flag
    /// without a value ("--torque") has an empty value.
    std::vector<std::pair<std::string, std::string>> options;
};

/// The texts of the study's base scenarios, in StudySpec::bases order.
/// @throws graspsim::InputError naming a base that is neither built in nor a readable file.
std::vector<scenario::ScenarioText> readBaseScenarios(const StudySpec& spec);

/// All base scenario texts joined (what a study folder's fingerprint covers).
std::string joinBaseTexts(const std::vector<scenario::ScenarioText>& bases);

/// The setup of `studyCase`: the study's `set:` values and the case's axis values on its base
/// (the one its "base" axis value names, or the study's only base).
/// @param bases the texts of StudySpec::bases, in order (readBaseScenarios).
/// @throws graspsim::InputError with the reader's or the option parser's message, prefixed by
/// the case number, when the combination is not accepted.
CaseSetup makeCaseSetup(const StudySpec& spec, const std::vector<scenario::ScenarioText>& bases,
                        const StudyCase& studyCase);

/// Checks, before anything runs, that each base scenario reads, that the `set:` values are
/// accepted on each, and that each axis value is accepted on its own (on a range, both ends).
/// Combinations are left to the cases (a failing case is recorded, the others run).
/// @throws graspsim::InputError with one line naming the study file, the line, the axis or
/// field, the value and what the reader accepts.
void checkStudyValues(const StudySpec& spec, const std::vector<scenario::ScenarioText>& bases);

}  // namespace graspsim::study
