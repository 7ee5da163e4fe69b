#include "approx_only_options.h"

#include "graspsim/error.h"

namespace graspsim::cli {

void checkApproxOnlyOptions(const CLI::App& command, const std::string& mode, const std::vector<std::string>& names) {
    if (mode == "approx") return;
    for (const std::string& name : names) {
        const CLI::Option* option = command.get_option_no_throw(name);
        if (option == nullptr || option->count() == 0) continue;
        const std::string value = option->results().empty() ? "" : option->results().front();
        throw InputError(name + ": value '" + value + "' is not accepted with --mode " + mode +
                         "; it is an option of the grasp approximation: add --mode approx or leave " + name + " out");
    }
}

}  // namespace graspsim::cli
