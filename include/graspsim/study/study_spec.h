#pragma once
/// @file
/// A study: one base scenario run many times, with scenario fields and run options varied along
/// axes, and the measures to collect from each run's summary.json (`graspsim simulate`) or
/// capacity.json (`graspsim capacity`, `command: capacity`).
///
/// A study is read from a commented YAML file; models/studies/stature-friction.yaml documents
/// every key. Values stay as the YAML text the file gives ("1.75", "[0, -9.5, 0]", "approx"):
/// the scenario reader and the run-option parsers check them, so their messages are the ones
/// a user already knows from `graspsim simulate`. One exception: a capacity study's direction
/// written as a list of three numbers, [0, -1, 0], is kept as the text `graspsim capacity
/// --direction` takes, "0,-1,0".

#include <cstdint>
#include <string>
#include <vector>

namespace graspsim::study {

/// What each case runs: `graspsim simulate` (the default) or `graspsim capacity` (study key
/// `command`).
enum class StudyCommand {
    Simulate,  ///< measures from the run's summary.json
    Capacity   ///< one load direction per case; measures from capacity.json's measurement
};

/// "simulate" or "capacity".
std::string toString(StudyCommand command);

/// The results file a case of `command` writes: "summary.json" or "capacity.json".
std::string nameResultFile(StudyCommand command);

/// Every run option a study may set or vary, by its study-file name: the union of both commands'.
const std::vector<std::string>& getRunOptionNames();

/// The run options of `command`, by study-file name. Both: "mode", "contact", "constraint",
/// "attach", "integrator"; simulate: "perturbation"; capacity: "direction", "torque" (true or
/// false: the flag), "rate", "method" (ramp, bisection, constant), "load", "hold",
/// "max_duration", "slip_threshold" (as the command's options, `_` for `-`).
const std::vector<std::string>& getRunOptionNames(StudyCommand command);

/// The measures a study of `command` may collect: keys of a run's summary.json ("held",
/// "object_displacement_m", "wall_time_s", "q_at_engage_n", ...), or of capacity.json's
/// measurement ("slip_onset_n", "drop_n", "grip_force_start_n", ...).
const std::vector<std::string>& getMeasureNames(StudyCommand command = StudyCommand::Simulate);

/// A numeric interval: `steps` evenly spaced values from `from` to `to` (both included) on a
/// grid, or uniformly drawn values in [from, to] when sampling.
struct ValueRange {
    double from = 0;
    double to = 0;
    int steps = 0;  ///< >= 2 on a grid; 0 when not given (sampling only)
};

/// One varied quantity: a scenario field by its dotted path ("subject.stature",
/// "perturbations.f1.force") or a run option ("mode").
struct StudyAxis {
    std::string name;                 ///< the path or option name, as the study file writes it
    bool isRunOption = false;         ///< true for mode, contact, ... (see getRunOptionNames)
    bool isBase = false;              ///< true for the axis "base": a list of base scenarios
    std::vector<std::string> values;  ///< YAML texts of a list axis; empty for a range axis
    bool isRange = false;             ///< true: `range` holds the values
    ValueRange range;
    int line = 0;                     ///< line of the axis in the study file (messages)
};

/// A field or option given one value for every case (section `set:`).
struct FixedValue {
    std::string name;
    bool isRunOption = false;
    std::string value;  ///< YAML text
    int line = 0;
};

/// How the cases are chosen from the axes.
enum class Sampling {
    Grid,    ///< every combination of every axis's values (full factorial)
    Random,  ///< `samples` cases, each axis drawn independently (seeded)
    Latin    ///< `samples` cases, a Latin hypercube: each axis's range cut into `samples` equal
             ///< strata, each stratum used once (seeded)
};

/// The whole study file.
struct StudySpec {
    std::string name;           ///< short identifier, e.g. "stature-friction"
    std::string description;    ///< may be empty
    std::string source;         ///< the study file's path (messages, the sbatch script)
    StudyCommand command = StudyCommand::Simulate;  ///< what each case runs
    /// The base scenarios: built-in names, or scenario file paths resolved against the study
    /// file's folder. One, or (`base:` given as a list) several: then the study's first axis is
    /// "base" (isBase), whose values are the list as the file writes it, in this order.
    std::vector<std::string> bases;
    std::vector<FixedValue> fixed;
    std::vector<StudyAxis> axes;  ///< in file order; the results table's columns
    Sampling sampling = Sampling::Grid;
    int samples = 0;            ///< Random and Latin: number of cases, >= 1
    std::uint64_t seed = 1;     ///< Random and Latin
    std::vector<std::string> measures;  ///< summary.json (capacity.json) keys, in table order
    std::string text;           ///< the study file's text (the output folder keeps a copy)
};

/// "grid", "random" or "latin".
std::string toString(Sampling sampling);

/// Reads the study file at `path`. Checks its structure, names, ranges and measures (a measure
/// that is also an axis or a `set:` key is refused: results.csv would have two such columns); the
/// values themselves are checked against the base scenario by checkStudyValues (case_setup.h).
/// @throws graspsim::InputError with one line naming the file, line, key and value.
StudySpec loadStudyFile(const std::string& path);

/// Parses study YAML text; `source` names it in messages and relative base paths are resolved
/// against its folder.
StudySpec parseStudy(const std::string& yamlText, const std::string& source);

}  // namespace graspsim::study
