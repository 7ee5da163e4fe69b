#pragma once
// `graspsim bench`: the thesis's Table 5.1 measured on this machine (cost_table.h).

#include <CLI/CLI.hpp>

#include <memory>

namespace graspsim::cli {

class BenchCommand {
public:
    explicit BenchCommand(CLI::App& app);
    bool parsed() const;
    int run() const;

private:
    struct Options;
    std::shared_ptr<Options> options_;
    CLI::App* command_ = nullptr;
};

}  // namespace graspsim::cli
