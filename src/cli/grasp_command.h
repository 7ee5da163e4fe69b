#pragma once
// `graspsim grasp plan`: plan a grasp for a subject, an object and a grasp type and write it as a
// scenario file. Parse, call the planning layer, write.

#include <CLI/CLI.hpp>

#include <memory>

namespace graspsim::cli {

// Registers the `grasp` command and its `plan` subcommand on `app`. The returned object holds
// the parsed option values and must outlive app.parse().
class GraspCommand {
public:
    explicit GraspCommand(CLI::App& app);
    // Checks the option values that need no planning (numbers, names); throws InputError.
    void checkOptions() const;
    // Plans and writes the scenario; returns the process exit code.
    int run() const;
    // True when the command line chose `grasp`.
    bool parsed() const;

private:
    struct Options;
    std::shared_ptr<Options> options_;
    CLI::App* grasp_ = nullptr;
    CLI::App* plan_ = nullptr;
};

}  // namespace graspsim::cli
