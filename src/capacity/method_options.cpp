#include "graspsim/capacity/method_options.h"

#include "graspsim/error.h"

#include <algorithm>

namespace graspsim::capacity {

namespace {

struct MethodOption {
    std::string name;
    std::vector<std::string> methods;
    std::string meaning;
};

const std::vector<MethodOption>& findTable() {
    static const std::vector<MethodOption> table{
        {"rate", {"ramp", "bisection", "compliance"}, "the ramp's rate, the compliance model's creep ramp's too; bisection's first load is rate x 1 s"},
        {"max_duration", {"ramp", "compliance"}, "the longest ramp"},
        {"initial_load", {"ramp"}, "the ramp's step at its start"},
        {"hold", {"bisection", "constant"}, "how long each constant load is held"},
        {"load", {"constant"}, "the constant load"},
        {"guess", {"bisection"}, "bisection's first load"},
    };
    return table;
}

std::string joinMethods(const std::string& methodWord, const std::vector<std::string>& methods) {
    std::string text = methodWord + " " + methods.front();
    for (std::size_t k = 1; k < methods.size(); ++k) text += (k + 1 == methods.size() ? " or " : ", ") + methods[k];
    return text;
}

}  // namespace

const std::vector<std::string>& findCapacityMethods() {
    static const std::vector<std::string> methods{"ramp", "bisection", "constant", "compliance"};
    return methods;
}

const std::vector<std::string>& findMethodOptionNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> n;
        for (const MethodOption& o : findTable()) n.push_back(o.name);
        return n;
    }();
    return names;
}

void checkMethodTakesOption(const std::string& method, const std::string& name,
                            const std::function<std::string(const std::string&)>& nameOf, const std::string& methodWord) {
    for (const MethodOption& o : findTable()) {
        if (o.name != name || std::find(o.methods.begin(), o.methods.end(), method) != o.methods.end()) continue;
        throw InputError(nameOf(o.name) + ": only with " + joinMethods(methodWord, o.methods) + " (" + o.meaning + "), not " + methodWord +
                         " " + method);
    }
}

void checkMethodOptions(const std::string& method, const std::vector<std::string>& given,
                        const std::function<std::string(const std::string&)>& nameOf, const std::string& methodWord) {
    for (const std::string& name : given) checkMethodTakesOption(method, name, nameOf, methodWord);
    if (method == "constant" && std::find(given.begin(), given.end(), "load") == given.end()) {
        throw InputError(nameOf("load") + ": missing; " + methodWord + " constant needs the load, N (N m with a torque), a number > 0");
    }
}

}  // namespace graspsim::capacity
