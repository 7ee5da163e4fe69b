#pragma once
// `graspsim validate`: the validation suite (validation_suite.h), its report and plots.

#include <CLI/CLI.hpp>

#include <memory>

namespace graspsim::cli {

class ValidateCommand {
public:
    explicit ValidateCommand(CLI::App& app);
    bool parsed() const;
    // Runs the suite; returns 0 when every bound holds, 4 when one fails.
    int run() const;

private:
    struct Options;
    std::shared_ptr<Options> options_;
    CLI::App* command_ = nullptr;
};

}  // namespace graspsim::cli
