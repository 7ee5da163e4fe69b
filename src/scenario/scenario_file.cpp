#include "graspsim/scenario/scenario_file.h"

#include "embedded_scenarios.h"
#include "scenario_reader.h"
#include "yaml_field.h"

#include "graspsim/error.h"
#include "graspsim/scenario/yaml_documents.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace graspsim::scenario {

namespace {

constexpr std::string_view kExtension = ".yaml";

// "ball-clutch.yaml" -> "ball-clutch"
std::string findBuiltinName(const EmbeddedFile& file) {
    return std::string(file.name.substr(0, file.name.size() - kExtension.size()));
}

// Messages about built-in scenarios name the file a user can read and copy.
std::string findBuiltinSource(const std::string& name) { return "models/scenarios/" + name + std::string(kExtension); }

std::string describeBuiltins() { return "built-in scenarios: " + joinBuiltinScenarioNames(); }

// yaml-cpp's marks count lines and columns from 0.
std::string describeMark(const YAML::Mark& mark) {
    if (mark.is_null()) return "";
    return std::to_string(mark.line + 1) + ":" + std::to_string(mark.column + 1) + ":";
}

}  // namespace

Scenario parseScenario(const std::string& yamlText, const std::string& source) {
    YAML::Node document;
    try {
        document = YAML::Load(yamlText);
    } catch (const YAML::Exception& e) {
        throw InputError(source + ":" + describeMark(e.mark) + " malformed YAML (" + e.msg +
                         "); a scenario file is a YAML map of 'key: value' lines, nested by indentation");
    }
    // YAML::Load reads the first document and silently drops the rest.
    if (const int line = findSecondYamlDocument(yamlText)) {
        throw InputError(source + ":" + std::to_string(line) + ": a second YAML document (after '---') is not " +
                         "accepted; a scenario file is one document");
    }
    try {
        return readScenario(YamlField::makeRoot(document, source));
    } catch (const YAML::Exception& e) {
        // The reader checks node types before converting, so this is a reader bug; still report
        // where in the file it happened rather than let a yaml-cpp exception escape.
        throw InputError(source + ":" + describeMark(e.mark) + " cannot read the scenario (" + e.msg + ")");
    }
}

namespace {

std::string readFileText(const std::string& path) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) {
        throw InputError(path + ": is not a readable file; give a scenario YAML file or one of the " +
                         describeBuiltins());
    }
    std::ifstream file(path, std::ios::binary);
    std::ostringstream text;
    text << file.rdbuf();
    if (!file) throw InputError(path + ": cannot be read; give a readable scenario YAML file");
    return text.str();
}

}  // namespace

Scenario loadScenarioFile(const std::string& path) { return parseScenario(readFileText(path), path); }

std::string joinBuiltinScenarioNames() { return joinNames(getBuiltinScenarioNames()); }

std::vector<std::string> getBuiltinScenarioNames() {
    std::vector<std::string> names;
    for (std::size_t i = 0; i < kEmbeddedFileCount; ++i) names.push_back(findBuiltinName(kEmbeddedFiles[i]));
    std::sort(names.begin(), names.end());
    return names;
}

Scenario findBuiltinScenario(const std::string& name) {
    for (std::size_t i = 0; i < kEmbeddedFileCount; ++i) {
        if (findBuiltinName(kEmbeddedFiles[i]) == name) {
            return parseScenario(std::string(kEmbeddedFiles[i].text), findBuiltinSource(name));
        }
    }
    throw InputError("scenario '" + name + "' is not accepted; " + describeBuiltins());
}

Scenario loadScenario(const std::string& nameOrPath) {
    const std::vector<std::string> names = getBuiltinScenarioNames();
    if (std::find(names.begin(), names.end(), nameOrPath) != names.end()) return findBuiltinScenario(nameOrPath);
    return loadScenarioFile(nameOrPath);
}

ScenarioText readScenarioText(const std::string& nameOrPath) {
    for (std::size_t i = 0; i < kEmbeddedFileCount; ++i) {
        if (findBuiltinName(kEmbeddedFiles[i]) == nameOrPath) {
            return {std::string(kEmbeddedFiles[i].text), findBuiltinSource(nameOrPath)};
        }
    }
    return {readFileText(nameOrPath), nameOrPath};
}

}  // namespace graspsim::scenario
