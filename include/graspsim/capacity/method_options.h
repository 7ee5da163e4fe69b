#pragma once
/// @file
/// Which capacity method takes which load option. `graspsim capacity`'s flags and a capacity
/// study's run options are checked against the same table, so that an option the method would
/// leave unused is refused rather than silently ignored.
///
/// Options by their study names (the command's flags are "--" + the name with '-' for '_'):
/// rate (ramp; bisection's first load is rate x 1 s; compliance, whose creep ramp follows the
/// load at that rate), max_duration (ramp, compliance), initial_load (ramp), hold (bisection,
/// constant), load (constant, which needs it), guess (bisection).

#include <functional>
#include <string>
#include <vector>

namespace graspsim::capacity {

/// The methods: "ramp", "bisection", "constant", "compliance".
const std::vector<std::string>& findCapacityMethods();

/// The load options of the file comment, in that order.
const std::vector<std::string>& findMethodOptionNames();

/// Refuses the option `name` (a study name) if `method` does not take it. `nameOf` turns a study
/// name into what the user wrote ("--max-duration", "run option 'max_duration'"); `methodWord` is
/// how the method is named ("--method", "method").
/// @throws graspsim::InputError "<option>: only with <methodWord> <methods> (<what it is>), not <methodWord> <method>".
void checkMethodTakesOption(const std::string& method, const std::string& name,
                            const std::function<std::string(const std::string&)>& nameOf, const std::string& methodWord);

/// Refuses each of the options `given` that `method` does not take (checkMethodTakesOption), and
/// a constant load without `load`.
/// @throws graspsim::InputError as checkMethodTakesOption, or "<load>: missing; ...".
void checkMethodOptions(const std::string& method, const std::vector<std::string>& given,
                        const std::function<std::string(const std::string&)>& nameOf, const std::string& methodWord);

}  // namespace graspsim::capacity
