#include "command_line.h"

#include "graspsim/error.h"
#include "graspsim/results/provenance.h"

#include <iostream>
#include <vector>
#include <sstream>
#include <iterator>

namespace graspsim::cli {

CommandLine::CommandLine()
    : app_("graspsim: anthropometric grasp simulation on Simbody"), model_(app_), simulate_(app_), validate_(app_), bench_(app_), study_(app_), view_(app_), capacity_(app_), grasp_(app_) {
    app_.require_subcommand(0, 1);  // none given: say which exist; unknown ones: CLI11 names them
    // Version, commit and library versions: what provenance.json records for each result.
    app_.set_version_flag("--version", [] {
        std::string text = results::formatVersionText(results::findBuildProvenance());
        text.pop_back();  // CLI11 ends the line itself
        return text;
    });
}

namespace {

// The commands read an option's empty text as "not given": `--duration ''` would silently run the
// scenario's duration. Flags (no value) are skipped; CLI11 lists only the parsed subcommands.
void rejectEmptyValues(const CLI::App& app) {
    for (const CLI::Option* option : app.get_options()) {
        if (option->get_type_size_max() == 0) continue;
        for (const std::string& value : option->results()) {
            if (!value.empty()) continue;
            throw InputError(option->get_name() + ": value '' (empty) is not accepted; give a value" +
                             (option->get_required() ? std::string() : " or leave " + option->get_name() + " out"));
        }
    }
    for (const CLI::App* command : app.get_subcommands()) rejectEmptyValues(*command);
}

}  // namespace

void CommandLine::parse(int argc, const char* const* argv) {
    arguments_.assign(argv, argv + argc);
    app_.parse(argc, argv);
    rejectEmptyValues(app_);
}

void CommandLine::checkOptions() const {
    if (simulate_.parsed()) simulate_.checkOptions();
    if (model_.parsed()) model_.checkOptions();
    if (study_.parsed()) study_.checkOptions();
    if (capacity_.parsed()) capacity_.checkOptions();
    if (grasp_.parsed()) grasp_.checkOptions();
}

int CommandLine::run() const {
    if (simulate_.parsed()) return simulate_.run(arguments_);
    if (view_.parsed()) return view_.run();
    if (validate_.parsed()) return validate_.run();
    if (bench_.parsed()) return bench_.run();
    if (study_.parsed()) return study_.run();
    if (capacity_.parsed()) return capacity_.run();
    if (grasp_.parsed()) return grasp_.run();
    if (!model_.parsed()) throw InputError("a command is required: model, grasp, simulate, view, capacity, validate, bench or study (see graspsim --help)");
    return model_.run();
}

int CommandLine::exit(const CLI::ParseError& e) {
    // Help and version requests are "errors" with exit code 0: let CLI11 print the help of
    // whichever (sub)command asked. Real parse errors get one line.
    if (e.get_exit_code() == 0) return app_.exit(e);
    std::string message = e.what();
    // CLI11 says "--duration: At Most 1 required but received 3" of an option given twice.
    const std::string repeated = ": At Most 1 required but received ";
    const std::size_t at = message.find(repeated);
    if (at != std::string::npos) message = message.substr(0, at) + ": given more than once; give each option once";
    // CLI11 lists what it did not expect last first ("...not expected: 0.1 --output-interval").
    const std::string extras = "The following argument";
    if (message.rfind(extras, 0) == 0 && message.find(": ") != std::string::npos) {
        std::istringstream words(message.substr(message.find(": ") + 2));
        std::vector<std::string> given{std::istream_iterator<std::string>(words), std::istream_iterator<std::string>()};
        std::string text;
        for (auto it = given.rbegin(); it != given.rend(); ++it) text += (text.empty() ? "" : " ") + *it;
        message = "not an option or argument of this command: " + text;
    }
    std::cerr << "graspsim: " << message << " (see graspsim --help)\n";
    return 2;
}

}  // namespace graspsim::cli
