#include "graspsim/capacity/method_options.h"

#include "graspsim/error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace {

using graspsim::capacity::checkMethodOptions;

std::string refusalOf(const std::string& method, const std::vector<std::string>& given) {
    try {
        checkMethodOptions(method, given, [](const std::string& name) { return "<" + name + ">"; }, "--method");
    } catch (const graspsim::InputError& e) {
        return e.what();
    }
    return "accepted";
}

// The table of the file comment, option by option: each method takes its own and refuses the rest.
TEST(MethodOptions, EachMethodTakesItsOwnLoadOptionsOnly) {
    const std::vector<std::string> options{"rate", "max_duration", "initial_load", "hold", "load", "guess"};
    EXPECT_EQ(graspsim::capacity::findMethodOptionNames(), options);
    const std::vector<std::vector<std::string>> taken{
        {"rate", "max_duration", "initial_load"},   // ramp
        {"rate", "hold", "guess"},                  // bisection
        {"hold", "load"},                           // constant
        {"rate", "max_duration"},                   // compliance: its creep ramp's
    };
    const std::vector<std::string>& methods = graspsim::capacity::findCapacityMethods();
    ASSERT_EQ(methods.size(), taken.size());
    for (std::size_t m = 0; m < methods.size(); ++m) {
        for (const std::string& option : options) {
            const bool takes = std::find(taken[m].begin(), taken[m].end(), option) != taken[m].end();
            std::vector<std::string> given{option};
            if (methods[m] == "constant" && option != "load") given.push_back("load");
            const std::string refusal = refusalOf(methods[m], given);
            EXPECT_EQ(refusal == "accepted", takes) << methods[m] << " " << option << ": " << refusal;
            if (takes) continue;
            EXPECT_EQ(refusal.rfind("<" + option + ">: only with --method ", 0), 0u) << refusal;
            EXPECT_NE(refusal.find("not --method " + methods[m]), std::string::npos) << refusal;
        }
    }
}

TEST(MethodOptions, AConstantLoadNeedsItsLoad) {
    EXPECT_EQ(refusalOf("constant", {"hold"}), "<load>: missing; --method constant needs the load, N (N m with a torque), a number > 0");
    EXPECT_EQ(refusalOf("ramp", {}), "accepted");
}

}  // namespace
