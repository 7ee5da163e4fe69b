#pragma once
// `graspsim study run | submit | collect`: parameter sweeps over a base scenario, on local
// processes or as a Slurm job array (library: src/study).

#include <CLI/CLI.hpp>

#include <memory>

namespace graspsim::cli {

class StudyCommand {
public:
    explicit StudyCommand(CLI::App& app);
    bool parsed() const;
    // Checks the option values that need no file (jobs, shard, array size); throws InputError.
    void checkOptions() const;
    // Runs the parsed subcommand; returns the exit code (0, or 5 when collect finds cases missing).
    int run() const;

private:
    int runCases() const;
    int submit() const;
    int collect() const;

    struct Options;
    std::shared_ptr<Options> options_;
    CLI::App* command_ = nullptr;
    CLI::App* run_ = nullptr;
    CLI::App* submit_ = nullptr;
    CLI::App* collect_ = nullptr;
};

}  // namespace graspsim::cli
