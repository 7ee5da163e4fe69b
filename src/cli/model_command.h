#pragma once
// `graspsim model build` and `graspsim model info`: parse, call the library, print.

#include <CLI/CLI.hpp>

#include <memory>

namespace graspsim::cli {

// Registers the `model` command and its subcommands on `app`. The returned object holds the
// parsed option values and must outlive app.parse().
class ModelCommand {
public:
    explicit ModelCommand(CLI::App& app);
    // Checks the option values that need no file (numbers, ranges, names); throws InputError.
    void checkOptions() const;
    // Runs whichever subcommand was parsed; returns the process exit code.
    int run() const;
    // True when the command line chose `model`.
    bool parsed() const;

private:
    struct Options;
    std::shared_ptr<Options> options_;
    CLI::App* model_ = nullptr;
    CLI::App* build_ = nullptr;
    CLI::App* object_ = nullptr;
    CLI::App* info_ = nullptr;
};

}  // namespace graspsim::cli
