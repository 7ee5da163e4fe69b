// graspsim's command line: thin. Parse, call the library, map errors to exit codes:
// 0 success, 2 bad input (one line on stderr), 3 numerical failure, 4 a validation bound failed,
// 1 anything unexpected.

#include "bench_command.h"
#include "model_command.h"
#include "simulate_command.h"
#include "validate_command.h"

#include "graspsim/error.h"

#include <CLI/CLI.hpp>

#include <iostream>

int main(int argc, char** argv) {
    CLI::App app{"graspsim: anthropometric grasp simulation on Simbody"};
    app.require_subcommand(0, 1);  // none given: say which exist; unknown ones: CLI11 names them
    app.set_version_flag("--version", "graspsim 0.1.0");
    graspsim::cli::ModelCommand model(app);
    graspsim::cli::SimulateCommand simulate(app);
    graspsim::cli::ValidateCommand validate(app);
    graspsim::cli::BenchCommand bench(app);
    try {
        app.parse(argc, argv);
        if (simulate.parsed()) return simulate.run();
        if (validate.parsed()) return validate.run();
        if (bench.parsed()) return bench.run();
        if (!model.parsed()) throw graspsim::InputError("a command is required: model, simulate, validate or bench (see graspsim --help)");
        return model.run();
    } catch (const CLI::ParseError& e) {
        // Help and version requests are "errors" with exit code 0: let CLI11 print the help of
        // whichever (sub)command asked. Real parse errors get one line.
        if (e.get_exit_code() == 0) return app.exit(e);
        std::cerr << "graspsim: " << e.what() << " (see graspsim --help)\n";
        return 2;
    } catch (const graspsim::InputError& e) {
        std::cerr << "graspsim: " << e.what() << "\n";
        return 2;
    } catch (const graspsim::NumericalError& e) {
        std::cerr << "graspsim: " << e.what() << "\n";
        return 3;
    } catch (const std::exception& e) {
        std::cerr << "graspsim: internal error: " << e.what() << "\n";
        return 1;
    }
}
