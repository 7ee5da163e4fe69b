#pragma once
/// @file
/// Reading scenarios from commented YAML files, and the built-in scenarios of the thesis.
///
/// A scenario file is a YAML map; models/scenarios/ball-clutch.yaml documents every key with its
/// unit and default. Lengths are metres, masses kilograms, times seconds, forces newtons, angles
/// DEGREES (joint angles of the grasp pose, the object's Euler angles); inside graspsim the
/// angles are radians. Required: name, object (shape, mass, radius or size, position),
/// grasp_pose, goals; or, instead of grasp_pose, goals and the object's position and orientation,
/// `grasp: {type: ...}` (Scenario::graspType), which planning/planned_scenario.h plans. Every other section and key is optional and falls back to the defaults of
/// scenario.h.
///
/// Every error is a graspsim::InputError with one line naming the file, the line, the field
/// path, the value and what is accepted, e.g.
/// "my.yaml:12: field 'object.mass' value '-0.2' is not accepted; mass must be a finite number > 0 kg".
/// Missing required fields, unknown (mistyped) keys, keys given twice, wrong types, values out of
/// range, grasp-pose joints the arm does not have or angles outside their range of motion, goals
/// more than 1 mm off the object's surface and malformed YAML are all reported this way.

#include "graspsim/scenario/scenario.h"

#include <string>
#include <vector>

namespace graspsim::scenario {

/// Reads the scenario file at `path`.
/// @throws graspsim::InputError when the file cannot be read or is not an accepted scenario.
Scenario loadScenarioFile(const std::string& path);

/// Parses scenario YAML text. `source` names the text in messages (usually its file name).
/// @throws graspsim::InputError when the text is not an accepted scenario.
Scenario parseScenario(const std::string& yamlText, const std::string& source);

/// The names of the built-in scenarios ("ball-clutch", "phone-pinch", ...), sorted.
std::vector<std::string> getBuiltinScenarioNames();

/// The same names joined, "ball-clutch, ball-tripod, ...", for help texts and messages.
std::string joinBuiltinScenarioNames();

/// The built-in scenario `name`: `models/scenarios/<name>.yaml`, compiled into the library.
/// @throws graspsim::InputError listing the built-in names when there is none called `name`.
Scenario findBuiltinScenario(const std::string& name);

/// A built-in scenario when `nameOrPath` is one's name, otherwise the scenario file at that path.
/// @throws graspsim::InputError as findBuiltinScenario and loadScenarioFile.
Scenario loadScenario(const std::string& nameOrPath);

/// A scenario's YAML text, unparsed, and the name messages give it.
struct ScenarioText {
    std::string text;    ///< the file's YAML, comments included
    std::string source;  ///< "models/scenarios/ball-clutch.yaml" for a built-in, else the path
};

/// The text of the built-in scenario `nameOrPath`, or of the file at that path (not checked:
/// give it to parseScenario). For tools that edit fields before parsing (study cases).
/// @throws graspsim::InputError when there is no such built-in and the file cannot be read.
ScenarioText readScenarioText(const std::string& nameOrPath);

}  // namespace graspsim::scenario
