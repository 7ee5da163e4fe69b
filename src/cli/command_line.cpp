#include "command_line.h"

#include "graspsim/error.h"

#include <iostream>

namespace graspsim::cli {

CommandLine::CommandLine()
    : app_("graspsim: anthropometric grasp simulation on Simbody"), model_(app_), simulate_(app_), validate_(app_), bench_(app_), capacity_(app_) {
    app_.require_subcommand(0, 1);  // none given: say which exist; unknown ones: CLI11 names them
    app_.set_version_flag("--version", "graspsim 0.1.0");
}

void CommandLine::parse(int argc, const char* const* argv) { app_.parse(argc, argv); }

void CommandLine::checkOptions() const {
    if (simulate_.parsed()) simulate_.checkOptions();
    if (model_.parsed()) model_.checkOptions();
    if (capacity_.parsed()) capacity_.checkOptions();
}

int CommandLine::run() const {
    if (simulate_.parsed()) return simulate_.run();
    if (validate_.parsed()) return validate_.run();
    if (bench_.parsed()) return bench_.run();
    if (capacity_.parsed()) return capacity_.run();
    if (!model_.parsed()) throw InputError("a command is required: model, simulate, capacity, validate or bench (see graspsim --help)");
    return model_.run();
}

int CommandLine::exit(const CLI::ParseError& e) {
    // Help and version requests are "errors" with exit code 0: let CLI11 print the help of
    // whichever (sub)command asked. Real parse errors get one line.
    if (e.get_exit_code() == 0) return app_.exit(e);
    std::cerr << "graspsim: " << e.what() << " (see graspsim --help)\n";
    return 2;
}

}  // namespace graspsim::cli
