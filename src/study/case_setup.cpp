#include "graspsim/study/case_setup.h"

#include "graspsim/capacity/capacity_trace.h"
#include "graspsim/capacity/load_direction.h"
#include "graspsim/capacity/method_options.h"
#include "graspsim/error.h"
#include "graspsim/io/number_text.h"
#include "graspsim/simulation/simulation_options.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace graspsim::study {

namespace {

// A field or option and its YAML text value.
struct Assignment {
    std::string name;
    bool isRunOption = false;
    std::string value;
};

std::vector<std::string> splitPath(const std::string& path) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    for (std::size_t dot = path.find('.'); dot != std::string::npos; dot = path.find('.', start)) {
        parts.push_back(path.substr(start, dot - start));
        start = dot + 1;
    }
    parts.push_back(path.substr(start));
    return parts;
}

YAML::Node loadValue(const std::string& path, const std::string& value) {
    try {
        return YAML::Load(value);
    } catch (const YAML::Exception& e) {
        throw InputError("field '" + path + "' value '" + value + "' is not accepted; it is not a YAML value (" + e.msg + ")");
    }
}

// Writes `value` at `path` in the document, adding missing sections; a path through a value that
// is not a section cannot name a field.
void writeField(YAML::Node& root, const std::string& path, const std::string& value) {
    const std::vector<std::string> parts = splitPath(path);
    YAML::Node node = root;
    std::string walked;
    for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
        walked += (walked.empty() ? "" : ".") + parts[i];
        YAML::Node child = node[parts[i]];
        if (!child.IsDefined() || child.IsNull()) {
            node[parts[i]] = YAML::Node(YAML::NodeType::Map);
            child = node[parts[i]];
        }
        if (!child.IsMap()) {
            throw InputError("field '" + path + "' is not accepted; '" + walked + "' is a value, not a section with fields");
        }
        node.reset(child);  // rebinds; '=' would overwrite the parent's content
    }
    node[parts.back()] = loadValue(path, value);
}

// The scenario reader's message without its "<source>:<line>: " start: the line is the edited
// text's, which the user never sees.
std::string stripPlace(const std::string& message, const std::string& source) {
    if (message.rfind(source + ":", 0) != 0) return message;
    std::size_t at = source.size() + 1;
    while (at < message.size() && (std::isdigit(static_cast<unsigned char>(message[at])) || message[at] == ':')) ++at;
    while (at < message.size() && message[at] == ' ') ++at;
    return message.substr(at);
}

// A capacity option's number, as the command accepts it; a study has no empty flag to leave out.
void checkPositiveNumber(const std::string& source, const std::string& value, const char* unit) {
    if (!io::parsePositiveNumber(value, source, unit)) throw InputError(source + ": no value; give a finite number > 0 (" + unit + ")");
}

// The capacity options; the command itself checks how they combine (a constant load needs load).
void checkCapacityOption(const std::string& name, const std::string& value) {
    const std::string source = "run option '" + name + "'";
    if (name == "direction") {
        if (value == "all") throw InputError(source + ": 'all' is not accepted in a study; make direction an axis of the directions");
        capacity::parseLoadDirection(value, source);
    }
    if (name == "torque" && value != "true" && value != "false") {
        throw InputError(source + ": '" + value + "' is not accepted; true (a torque about the centre of mass) or false (a force)");
    }
    if (name == "method" && value != "ramp" && value != "bisection" && value != "constant") {
        throw InputError(source + ": '" + value + "' is not accepted; ramp, bisection or constant");
    }
    if (name == "rate") checkPositiveNumber(source, value, "N/s, N m/s with torque");
    if (name == "load") checkPositiveNumber(source, value, "N, N m with torque");
    if (name == "hold" || name == "max_duration") checkPositiveNumber(source, value, "s");
    if (name == "slip_threshold") {
        checkPositiveNumber(source, value, "m");
        capacity::SlipCriteria criteria;  // a study does not change the drop threshold
        criteria.slip = std::strtod(value.c_str(), nullptr);
        capacity::checkSlipCriteria(criteria, source, value);
    }
}

std::string checkRunOption(const std::string& name, const std::string& value, const scenario::Scenario& scenario) {
    const std::string source = "run option '" + name + "'";
    checkCapacityOption(name, value);
    if (name == "mode") simulation::parseSimulationMode(value, source);
    if (name == "contact") simulation::parseContactModel(value, source);
    if (name == "constraint") simulation::parseApproxConstraint(value, source);
    if (name == "attach") simulation::parseApproxAttach(value, source);
    if (name == "bushing_give") simulation::parseApproxBushingGive(value, source);
    if (name == "release_at") simulation::parseApproxReleaseTrigger(value, source);
    if (name == "hand_back") simulation::parseApproxHandBack(value, source);
    if (name == "release_give") checkPositiveNumber(source, value, "m");
    if (name == "release_creep" && value != "on" && value != "off") {
        throw InputError(source + ": '" + value + "' is not accepted; on or off");
    }
    if (name == "integrator") simulation::parseIntegratorChoice(value, source);
    if (name == "perturbation" && value != "none" && !scenario.findPerturbation(value)) {
        std::string known = "none";
        for (const auto& p : scenario.perturbations) known += ", " + p.name;
        throw InputError(source + ": '" + value + "' is not accepted; the scenario has " + known);
    }
    return value;
}

// The grasp approximation's own run options, which simulate and capacity refuse without --mode approx.
bool isApproxOnly(const std::string& option) {
    static const std::vector<std::string> names{"constraint", "attach", "bushing_give", "release_at", "release_give", "release_creep", "hand_back"};
    return std::find(names.begin(), names.end(), option) != names.end();
}

// The command's flag for a study option: max_duration is --max-duration.
std::string formatFlag(const std::string& option) {
    std::string flag = "--" + option;
    std::replace(flag.begin(), flag.end(), '_', '-');
    return flag;
}

// The run options in getRunOptionNames order. The approximation's constraint and attachment (a
// study's set, for its approx cases) are not given to a full-contact case: simulate refuses them
// without --mode approx. torque is a flag: given (with no value) when true.
std::vector<std::pair<std::string, std::string>> listRunOptions(const std::vector<Assignment>& assignments,
                                                                 const scenario::Scenario& parsed, StudyCommand command) {
    std::vector<std::pair<std::string, std::string>> options;
    bool approx = false;
    for (const Assignment& a : assignments) approx = approx || (a.isRunOption && a.name == "mode" && a.value == "approx");
    for (const std::string& option : getRunOptionNames(command)) {
        const bool approxOnly = isApproxOnly(option);
        for (const Assignment& a : assignments) {
            if (!a.isRunOption || a.name != option) continue;
            // Checked for every case, also one it is not given to: a bad value fails before anything runs.
            const std::string value = checkRunOption(a.name, a.value, parsed);
            if (approxOnly && !approx) continue;
            if (option == "torque") {
                if (value == "true") options.emplace_back("--torque", "");
                continue;
            }
            options.emplace_back(formatFlag(option), value);
        }
    }
    return options;
}

// The base with `assignments` applied, parsed; the options in getRunOptionNames order.
CaseSetup applyAssignments(const scenario::ScenarioText& base, const std::vector<Assignment>& assignments, StudyCommand command) {
    YAML::Node root = YAML::Load(base.text);
    for (const Assignment& a : assignments) {
        if (!a.isRunOption) writeField(root, a.name, a.value);
    }
    YAML::Emitter out;
    out << root;
    CaseSetup setup{std::string(out.c_str()) + "\n", {}};
    const std::string source = base.source + " (edited)";
    scenario::Scenario parsed;
    try {
        parsed = scenario::parseScenario(setup.scenarioYaml, source);
    } catch (const InputError& e) {
        throw InputError(stripPlace(e.what(), source));
    }
    setup.options = listRunOptions(assignments, parsed, command);
    return setup;
}

std::vector<Assignment> listFixed(const StudySpec& spec) {
    std::vector<Assignment> assignments;
    for (const FixedValue& f : spec.fixed) assignments.push_back({f.name, f.isRunOption, f.value});
    return assignments;
}

std::string formatEnd(double value) {
    char text[40];
    std::snprintf(text, sizeof text, "%.12g", value);
    return text;
}

std::string place(const StudySpec& spec, int line) { return spec.source + ":" + std::to_string(line) + ": "; }

// A study without mode runs full contact only, where the approximation's constraint and
// attachment would be silently unused.
void checkApproxOnlyRunOptions(const StudySpec& spec) {
    bool modeGiven = false;
    for (const FixedValue& f : spec.fixed) modeGiven = modeGiven || f.name == "mode";
    for (const StudyAxis& axis : spec.axes) modeGiven = modeGiven || axis.name == "mode";
    if (modeGiven) return;
    const auto refuse = [&](const std::string& name, int line) {
        if (!isApproxOnly(name)) return;
        throw InputError(place(spec, line) + "run option '" + name + "' is not accepted without mode approx (set or an axis); "
                         "it is an option of the grasp approximation");
    };
    for (const FixedValue& f : spec.fixed) refuse(f.name, f.line);
    for (const StudyAxis& axis : spec.axes) refuse(axis.name, axis.line);
}

// A capacity study's load options against each method it runs (method_options.h): an option the
// method would leave unused, or a constant load without one, would fail every such case.
void checkCapacityMethodRunOptions(const StudySpec& spec) {
    if (spec.command != StudyCommand::Capacity) return;
    std::vector<std::string> methods{"ramp"}, given;
    std::vector<int> lines;
    int methodLine = 1;
    const auto note = [&](const std::string& name, int line, const std::vector<std::string>& values) {
        const std::vector<std::string>& options = capacity::findMethodOptionNames();
        if (name == "method") {
            methods = values;
            methodLine = line;
        } else if (std::find(options.begin(), options.end(), name) != options.end()) {
            given.push_back(name);
            lines.push_back(line);
        }
    };
    for (const FixedValue& f : spec.fixed) note(f.name, f.line, {f.value});
    for (const StudyAxis& axis : spec.axes) note(axis.name, axis.line, axis.values);
    const auto nameOf = [](const std::string& name) { return "run option '" + name + "'"; };
    for (const std::string& method : methods) {
        for (std::size_t k = 0; k < given.size(); ++k) {
            try {
                capacity::checkMethodTakesOption(method, given[k], nameOf, "method");
            } catch (const InputError& e) {
                throw InputError(place(spec, lines[k]) + e.what());
            }
        }
        try {
            capacity::checkMethodOptions(method, given, nameOf, "method");
        } catch (const InputError& e) {
            throw InputError(place(spec, methodLine) + e.what());
        }
    }
}

}  // namespace

std::vector<scenario::ScenarioText> readBaseScenarios(const StudySpec& spec) {
    std::vector<scenario::ScenarioText> bases;
    for (const std::string& base : spec.bases) bases.push_back(scenario::readScenarioText(base));
    return bases;
}

std::string joinBaseTexts(const std::vector<scenario::ScenarioText>& bases) {
    std::string text;
    for (std::size_t b = 0; b < bases.size(); ++b) text += (b == 0 ? "" : std::string(1, '\0')) + bases[b].text;
    return text;
}

CaseSetup makeCaseSetup(const StudySpec& spec, const std::vector<scenario::ScenarioText>& bases,
                        const StudyCase& studyCase) {
    std::vector<Assignment> assignments = listFixed(spec);
    std::size_t base = 0;
    for (std::size_t a = 0; a < spec.axes.size(); ++a) {
        const StudyAxis& axis = spec.axes[a];
        if (axis.isBase) {
            base = static_cast<std::size_t>(std::find(axis.values.begin(), axis.values.end(), studyCase.values[a]) -
                                            axis.values.begin());
            continue;
        }
        assignments.push_back({axis.name, axis.isRunOption, studyCase.values[a]});
    }
    if (base >= bases.size()) throw InputError("case " + std::to_string(studyCase.index) + ": its base is not one of the study's");
    return applyAssignments(bases[base], assignments, spec.command);
}

void checkStudyValues(const StudySpec& spec, const std::vector<scenario::ScenarioText>& bases) {
    checkApproxOnlyRunOptions(spec);
    const std::vector<Assignment> fixed = listFixed(spec);
    for (const scenario::ScenarioText& base : bases) {
        try {
            applyAssignments(base, fixed, spec.command);
        } catch (const InputError& e) {
            throw InputError(place(spec, spec.fixed.empty() ? 1 : spec.fixed.front().line) + "base '" + base.source +
                             "' with the 'set' values: " + e.what());
        }
        for (const StudyAxis& axis : spec.axes) {
            if (axis.isBase) continue;
            std::vector<std::string> values = axis.values;
            if (axis.isRange) values = {formatEnd(axis.range.from), formatEnd(axis.range.to)};
            for (const std::string& value : values) {
                std::vector<Assignment> assignments = fixed;
                assignments.push_back({axis.name, axis.isRunOption, value});
                try {
                    applyAssignments(base, assignments, spec.command);
                } catch (const InputError& e) {
                    throw InputError(place(spec, axis.line) + "axis '" + axis.name + "'" +
                                     (bases.size() > 1 ? " on base '" + base.source + "'" : "") + ": " + e.what());
                }
            }
        }
    }
    checkCapacityMethodRunOptions(spec);  // after each value, so that a bad value is named first
}

}  // namespace graspsim::study
