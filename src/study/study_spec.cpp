#include "graspsim/study/study_spec.h"

#include "graspsim/error.h"
#include "graspsim/scenario/scenario_file.h"
#include "graspsim/scenario/yaml_documents.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace graspsim::study {

namespace {

// Case folders are numbered with at least four digits; a million cases is far beyond any study
// that finishes, and keeps a mistyped range from filling the disk.
constexpr int kMaxCases = 1000000;

const std::vector<std::string> kTopKeys{"name", "description", "command", "base", "set", "axes", "sampling", "samples", "seed", "measures"};

std::string join(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& n : names) text += (text.empty() ? "" : ", ") + n;
    return text;
}

int findLine(const YAML::Node& node) { return node.Mark().is_null() ? 1 : node.Mark().line + 1; }

// Every message starts with the file and line, then names the key: one line, as the scenario reader's.
[[noreturn]] void reject(const std::string& source, const YAML::Node& node, const std::string& what) {
    throw InputError(source + ":" + std::to_string(findLine(node)) + ": " + what);
}

// The value as flow YAML text: "1.75", "[0, -9.5, 0]", "approx".
std::string formatYaml(const YAML::Node& node) {
    YAML::Emitter out;
    out.SetSeqFormat(YAML::Flow);
    out.SetMapFormat(YAML::Flow);
    out << node;
    return out.c_str();
}

// A direction written as a YAML list, [0, -1, 0], becomes the text `graspsim capacity
// --direction` takes ("0,-1,0"), so that it reads as the command's vectors do; every other value
// stays YAML text (a scenario field's vector is written into the scenario as a list). A lone
// number is never a direction: on an axis it is most likely one direction's list written
// without its brackets, [0, -1, 0] for [[0, -1, 0]].
std::string formatValue(const std::string& source, const std::string& name, const YAML::Node& node, StudyCommand command) {
    if (command != StudyCommand::Capacity || name != "direction") return formatYaml(node);
    double number = 0;
    const bool isNumber = node.IsScalar() && YAML::convert<double>::decode(node, number);
    if (!node.IsSequence() && !isNumber) return formatYaml(node);
    bool ok = node.IsSequence() && node.size() == 3;
    std::string text;
    for (std::size_t k = 0; ok && k < node.size(); ++k) {
        ok = node[k].IsScalar() && YAML::convert<double>::decode(node[k], number) && std::isfinite(number);
        text += (text.empty() ? "" : ",") + (ok ? node[k].Scalar() : std::string());
    }
    if (!ok) {
        reject(source, node, "run option 'direction' value '" + formatYaml(node) +
                                 "' is not accepted; a direction is x, y, z, -x, -y, -z or a list of three numbers such as "
                                 "[0, -1, 0] (an axis lists directions: [[0, -1, 0], [1, 0, 0]])");
    }
    return text;
}

bool isRunOption(const std::string& name) {
    const auto& options = getRunOptionNames();
    return std::find(options.begin(), options.end(), name) != options.end();
}

// A capacity option that takes a number may be a range, as a scenario field may.
bool isNumericRunOption(const std::string& name) {
    return name == "rate" || name == "load" || name == "hold" || name == "max_duration" || name == "slip_threshold";
}

// A field path is dot-separated names; the scenario reader decides whether the field exists.
void checkName(const std::string& source, const YAML::Node& key, const std::string& name) {
    bool ok = !name.empty() && name.front() != '.' && name.back() != '.' && name.find("..") == std::string::npos;
    for (char c : name) ok = ok && (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '-');
    if (!ok) {
        reject(source, key, "axis '" + name + "' is not accepted; give a scenario field by its dotted path "
                            "(e.g. subject.stature) or a run option (" + join(getRunOptionNames()) + ")");
    }
}

std::string readText(const std::string& source, const YAML::Node& node, const std::string& key) {
    if (!node.IsScalar()) reject(source, node, "'" + key + "' is not accepted; give a text value");
    return node.Scalar();
}

double readNumber(const std::string& source, const YAML::Node& node, const std::string& key) {
    double value = 0;
    if (!node.IsScalar() || !YAML::convert<double>::decode(node, value) || !std::isfinite(value)) {
        reject(source, node, "'" + key + "' value '" + formatYaml(node) + "' is not accepted; give a finite number");
    }
    return value;
}

long readInteger(const std::string& source, const YAML::Node& node, const std::string& key, long lower) {
    long value = 0;
    if (!node.IsScalar() || !YAML::convert<long>::decode(node, value) || value < lower) {
        reject(source, node, "'" + key + "' value '" + formatYaml(node) + "' is not accepted; give a whole number >= " +
                                 std::to_string(lower));
    }
    return value;
}

ValueRange readRange(const std::string& source, const YAML::Node& node, const std::string& name) {
    for (const auto& entry : node) {
        const std::string key = entry.first.Scalar();
        if (key != "from" && key != "to" && key != "steps") {
            reject(source, entry.first, "axis '" + name + "' key '" + key + "' is not accepted; a range has from, to and steps");
        }
    }
    if (!node["from"] || !node["to"]) reject(source, node, "axis '" + name + "' range needs from and to (and steps on a grid)");
    ValueRange range{readNumber(source, node["from"], name + ".from"), readNumber(source, node["to"], name + ".to"), 0};
    if (node["steps"]) range.steps = static_cast<int>(readInteger(source, node["steps"], name + ".steps", 2));
    if (!(range.from < range.to)) {
        reject(source, node, "axis '" + name + "' range from " + formatYaml(node["from"]) + " to " + formatYaml(node["to"]) +
                                 " is not accepted; from must be below to");
    }
    return range;
}

StudyAxis readAxis(const std::string& source, const YAML::Node& key, const YAML::Node& value, StudyCommand command) {
    StudyAxis axis;
    axis.name = key.Scalar();
    checkName(source, key, axis.name);
    axis.isRunOption = isRunOption(axis.name);
    axis.line = findLine(key);
    if (value.IsSequence()) {
        std::set<std::string> seen;
        for (const auto& item : value) {
            axis.values.push_back(formatValue(source, axis.name, item, command));
            if (!seen.insert(axis.values.back()).second) {
                reject(source, item, "axis '" + axis.name + "' value '" + axis.values.back() + "' is listed twice; give each value once");
            }
        }
        if (axis.values.empty()) reject(source, key, "axis '" + axis.name + "' is empty; give a list of values or a range {from, to, steps}");
    } else if (value.IsMap() && (!axis.isRunOption || isNumericRunOption(axis.name))) {
        axis.isRange = true;
        axis.range = readRange(source, value, axis.name);
    } else {
        reject(source, key, "axis '" + axis.name + "' value '" + formatYaml(value) +
                                "' is not accepted; give a list of values" +
                                (axis.isRunOption && !isNumericRunOption(axis.name) ? "" : " or a range {from, to, steps}"));
    }
    return axis;
}

std::vector<StudyAxis> readAxes(const std::string& source, const YAML::Node& node, StudyCommand command) {
    if (!node || !node.IsMap() || node.size() == 0) {
        reject(source, node ? node : YAML::Node(), "'axes' is missing or empty; give a map of axis: [values] or axis: {from, to, steps}");
    }
    std::vector<StudyAxis> axes;
    std::set<std::string> seen;
    for (const auto& entry : node) {
        axes.push_back(readAxis(source, entry.first, entry.second, command));
        if (!seen.insert(axes.back().name).second) reject(source, entry.first, "axis '" + axes.back().name + "' is given twice");
    }
    return axes;
}

std::vector<FixedValue> readFixed(const std::string& source, const YAML::Node& node, StudyCommand command) {
    std::vector<FixedValue> fixed;
    if (!node || node.IsNull()) return fixed;
    if (!node.IsMap()) reject(source, node, "'set' is not accepted; give a map of field: value");
    std::set<std::string> seen;
    for (const auto& entry : node) {
        const std::string name = entry.first.Scalar();
        checkName(source, entry.first, name);
        if (!seen.insert(name).second) reject(source, entry.first, "set '" + name + "' is given twice; give each field once");
        fixed.push_back({name, isRunOption(name), formatValue(source, name, entry.second, command), findLine(entry.first)});
    }
    return fixed;
}

// A measure named as an axis would be a second column of that name in results.csv, and one named
// as a set key only repeats that value (capacity.json's rate is the rate the case ran at).
void checkMeasureIsNotGiven(const std::string& source, const YAML::Node& item, const std::string& name, const StudySpec& spec) {
    for (const StudyAxis& axis : spec.axes) {
        if (axis.name == name) reject(source, item, "measure '" + name + "' is also an axis; its values are in the axis column");
    }
    for (const FixedValue& f : spec.fixed) {
        if (f.name == name) {
            reject(source, item, "measure '" + name + "' is also a set key (line " + std::to_string(f.line) +
                                     "); every case has the value given there");
        }
    }
}

std::vector<std::string> readMeasures(const std::string& source, const YAML::Node& node, const StudySpec& spec) {
    const auto& known = getMeasureNames(spec.command);
    const std::string file = nameResultFile(spec.command);
    if (!node || !node.IsSequence() || node.size() == 0) {
        reject(source, node ? node : YAML::Node(), "'measures' is missing or empty; give a list of " + file + " keys: " + join(known));
    }
    std::vector<std::string> measures;
    for (const auto& item : node) {
        const std::string name = readText(source, item, "measures");
        if (std::find(known.begin(), known.end(), name) == known.end()) {
            reject(source, item, "measure '" + name + "' is not accepted; measures are " + file + " keys: " + join(known));
        }
        if (std::find(measures.begin(), measures.end(), name) != measures.end()) {
            reject(source, item, "measure '" + name + "' is listed twice; give each measure once");
        }
        checkMeasureIsNotGiven(source, item, name, spec);
        measures.push_back(name);
    }
    return measures;
}

StudyCommand readCommand(const std::string& source, const YAML::Node& node) {
    const std::string command = readText(source, node, "command");
    if (command == "simulate") return StudyCommand::Simulate;
    if (command == "capacity") return StudyCommand::Capacity;
    reject(source, node, "'command' value '" + command + "' is not accepted; simulate (default) or capacity");
}

// A run option of the other command (a load direction in a simulate study, a perturbation in a
// capacity study) would be refused by every case's process.
void checkCommandOptions(const StudySpec& spec) {
    const auto& own = getRunOptionNames(spec.command);
    const auto check = [&](const std::string& name, bool isOption, int line) {
        if (!isOption || std::find(own.begin(), own.end(), name) != own.end()) return;
        const std::string other = toString(spec.command == StudyCommand::Capacity ? StudyCommand::Simulate : StudyCommand::Capacity);
        throw InputError(spec.source + ":" + std::to_string(line) + ": run option '" + name + "' is not accepted with command: " +
                         toString(spec.command) + " (its options: " + join(own) + "); it is an option of command: " + other);
    };
    for (const FixedValue& f : spec.fixed) check(f.name, f.isRunOption, f.line);
    for (const StudyAxis& a : spec.axes) check(a.name, a.isRunOption, a.line);
}

// A base that is not a built-in name is a file path, relative to the study file's folder.
std::string resolveBase(const std::string& source, const std::string& base) {
    const auto builtins = scenario::getBuiltinScenarioNames();
    if (std::find(builtins.begin(), builtins.end(), base) != builtins.end()) return base;
    const std::filesystem::path path(base);
    if (path.is_absolute()) return base;
    return (std::filesystem::path(source).parent_path() / path).lexically_normal().string();
}

// `base: name` or `base: [name, ...]`; a list becomes the first axis, "base".
void readBases(const std::string& source, const YAML::Node& node, StudySpec& spec) {
    if (!node.IsSequence()) {
        spec.bases = {resolveBase(source, readText(source, node, "base"))};
        return;
    }
    StudyAxis axis;
    axis.name = "base";
    axis.isBase = true;
    axis.line = findLine(node);
    std::set<std::string> seen;
    for (const auto& item : node) {
        axis.values.push_back(readText(source, item, "base"));
        if (!seen.insert(axis.values.back()).second) reject(source, item, "base '" + axis.values.back() + "' is listed twice");
        spec.bases.push_back(resolveBase(source, axis.values.back()));
    }
    if (axis.values.empty()) reject(source, node, "'base' is an empty list; give a scenario or a list of scenarios");
    spec.axes.insert(spec.axes.begin(), axis);
}

void readSampling(const std::string& source, const YAML::Node& root, StudySpec& spec) {
    if (root["sampling"]) {
        const std::string sampling = readText(source, root["sampling"], "sampling");
        if (sampling == "grid") spec.sampling = Sampling::Grid;
        else if (sampling == "random") spec.sampling = Sampling::Random;
        else if (sampling == "latin") spec.sampling = Sampling::Latin;
        else reject(source, root["sampling"], "'sampling' value '" + sampling + "' is not accepted; grid, random or latin");
    }
    const bool sampled = spec.sampling != Sampling::Grid;
    if (sampled != bool(root["samples"])) {
        reject(source, root["samples"] ? root["samples"] : root,
               sampled ? "'samples' is missing; random and latin sampling need the number of cases" : "'samples' is not accepted with grid sampling");
    }
    if (sampled) spec.samples = static_cast<int>(readInteger(source, root["samples"], "samples", 1));
    if (!sampled && root["seed"]) reject(source, root["seed"], "'seed' is not accepted with grid sampling (it seeds random and latin)");
    if (root["seed"]) spec.seed = static_cast<std::uint64_t>(readInteger(source, root["seed"], "seed", 0));
    double gridSize = 1;
    for (const StudyAxis& axis : spec.axes) {
        if (!sampled && axis.isRange && axis.range.steps == 0) {
            throw InputError(source + ":" + std::to_string(axis.line) + ": axis '" + axis.name + "' range needs steps (>= 2) on a grid");
        }
        gridSize *= axis.isRange ? axis.range.steps : static_cast<double>(axis.values.size());
    }
    if (!sampled && gridSize > kMaxCases) {
        throw InputError(source + ": the grid has " + std::to_string(static_cast<long long>(gridSize)) + " cases, more than " +
                         std::to_string(kMaxCases) + "; use fewer values or sampling: random or latin with samples: N");
    }
    if (sampled && spec.samples > kMaxCases) reject(source, root["samples"], "'samples' is above " + std::to_string(kMaxCases));
}

}  // namespace

std::string toString(StudyCommand command) { return command == StudyCommand::Capacity ? "capacity" : "simulate"; }

std::string nameResultFile(StudyCommand command) { return command == StudyCommand::Capacity ? "capacity.json" : "summary.json"; }

const std::vector<std::string>& getRunOptionNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> all = getRunOptionNames(StudyCommand::Simulate);
        for (const std::string& name : getRunOptionNames(StudyCommand::Capacity)) {
            if (std::find(all.begin(), all.end(), name) == all.end()) all.push_back(name);
        }
        return all;
    }();
    return names;
}

const std::vector<std::string>& getRunOptionNames(StudyCommand command) {
    static const std::vector<std::string> simulate{"mode",         "contact",       "constraint", "attach",     "bushing_give", "release_at",
                                                   "release_give", "release_creep", "hand_back",  "integrator", "perturbation"};
    static const std::vector<std::string> capacity{"mode",          "contact",   "constraint", "attach",       "bushing_give",
                                                   "release_at",    "release_give", "release_creep", "hand_back", "integrator", "direction",
                                                   "torque", "rate", "method", "load", "hold", "max_duration", "slip_threshold"};
    return command == StudyCommand::Capacity ? capacity : simulate;
}

const std::vector<std::string>& getMeasureNames(StudyCommand command) {
    static const std::vector<std::string> capacity{
        "slip_onset_n", "drop_n", "slip_onset_nm", "drop_nm", "slip_onset_time_s", "drop_time_s", "max_load_n", "max_load_nm", "release_n", "release_nm",
        "release_time_s", "grip_force_start_n", "grip_force_onset_n", "rate", "load_n", "load_nm", "wall_time_s"};
    if (command == StudyCommand::Capacity) return capacity;
    static const std::vector<std::string> names{
        "held", "object_displacement_m", "max_penetration_m", "initial_penetration_m", "max_grasp_quality_n", "max_fingertip_goal_distance_m",
        "wall_time_s", "plan_time_s", "sim_time_s", "steps", "mean_step_us", "full_wall_s_per_sim_s", "engaged", "engage_time_s",
        "release_time_s", "q_at_engage_n", "q_threshold_n", "q_minimum_n", "min_engaged_grasp_quality_n",
        "max_engaged_penetration_growth_m", "max_release_velocity_jump_m_s", "approx_step_us"};
    return names;
}

std::string toString(Sampling sampling) {
    switch (sampling) {
        case Sampling::Grid: return "grid";
        case Sampling::Random: return "random";
        case Sampling::Latin: return "latin";
    }
    return "grid";
}

StudySpec parseStudy(const std::string& yamlText, const std::string& source) {
    YAML::Node root;
    try {
        root = YAML::Load(yamlText);
    } catch (const YAML::Exception& e) {
        throw InputError(source + ":" + std::to_string(e.mark.line + 1) + ": malformed YAML (" + e.msg + ")");
    }
    // YAML::Load reads the first document and silently drops the rest.
    if (const int line = scenario::findSecondYamlDocument(yamlText)) {
        throw InputError(source + ":" + std::to_string(line) + ": a second YAML document (after '---') is not accepted; a study file is one document");
    }
    if (!root.IsMap()) throw InputError(source + ": a study file is a YAML map (name, base, axes, measures, ...)");
    std::set<std::string> seen;
    for (const auto& entry : root) {
        const std::string key = entry.first.Scalar();
        if (std::find(kTopKeys.begin(), kTopKeys.end(), key) == kTopKeys.end()) {
            reject(source, entry.first, "key '" + key + "' is not accepted; a study has " + join(kTopKeys));
        }
        if (!seen.insert(key).second) reject(source, entry.first, "key '" + key + "' is given twice; give each key once");
    }
    StudySpec spec;
    spec.source = source;
    spec.text = yamlText;
    if (!root["name"]) throw InputError(source + ": 'name' is missing; give the study a short name");
    spec.name = readText(source, root["name"], "name");
    if (root["description"]) spec.description = readText(source, root["description"], "description");
    if (!root["base"]) throw InputError(source + ": 'base' is missing; give a built-in scenario (" + join(scenario::getBuiltinScenarioNames()) + ") or a scenario file");
    if (root["command"]) spec.command = readCommand(source, root["command"]);
    spec.fixed = readFixed(source, root["set"], spec.command);
    spec.axes = readAxes(source, root["axes"], spec.command);
    checkCommandOptions(spec);
    readBases(source, root["base"], spec);
    readSampling(source, root, spec);
    spec.measures = readMeasures(source, root["measures"], spec);
    for (const FixedValue& f : spec.fixed) {
        for (const StudyAxis& a : spec.axes) {
            if (a.name == f.name) throw InputError(source + ":" + std::to_string(f.line) + ": '" + f.name + "' is both set and an axis; keep one");
        }
    }
    return spec;
}

StudySpec loadStudyFile(const std::string& path) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) throw InputError(path + ": is not a readable file; give a study YAML file");
    std::ifstream file(path, std::ios::binary);
    std::ostringstream text;
    text << file.rdbuf();
    if (!file) throw InputError(path + ": cannot be read; give a readable study YAML file");
    return parseStudy(text.str(), path);
}

}  // namespace graspsim::study
