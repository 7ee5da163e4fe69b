#pragma once
// graspsim's whole command line (`model ...`, `simulate ...`, `validate ...`, `bench ...`, `study ...`, `view ...`) as one object, so that main() stays
// a few lines and the parsing can be exercised without a process (tests/fuzz).

#include "bench_command.h"
#include "capacity_command.h"
#include "grasp_command.h"
#include "model_command.h"
#include "simulate_command.h"
#include "study_command.h"
#include "validate_command.h"
#include "view_command.h"

#include <CLI/CLI.hpp>

namespace graspsim::cli {

class CommandLine {
public:
    CommandLine();
    CommandLine(const CommandLine&) = delete;
    CommandLine& operator=(const CommandLine&) = delete;

    // Parses the arguments (argv[0] is the program name).
    // Throws CLI::ParseError (also for --help and --version, exit code 0), InputError for an
    // option given an empty value.
    void parse(int argc, const char* const* argv);
    // Checks every option value that needs neither a file nor a simulation: numbers, ranges,
    // names. Throws InputError naming the option; run() checks the same values again.
    void checkOptions() const;
    // Runs the parsed command; returns the exit code. Throws InputError / NumericalError.
    int run() const;
    // Prints help or version (exit code 0) or the one-line parse error; returns the exit code.
    int exit(const CLI::ParseError& e);

private:
    CLI::App app_;
    std::vector<std::string> arguments_;  // argv as given, for the results' provenance
    ModelCommand model_;
    SimulateCommand simulate_;
    ValidateCommand validate_;
    BenchCommand bench_;
    StudyCommand study_;
    ViewCommand view_;
    CapacityCommand capacity_;
    GraspCommand grasp_;
};

}  // namespace graspsim::cli
