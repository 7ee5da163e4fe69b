#pragma once
// `graspsim view DIR`: write DIR/replay.html, the 3-D replay of a result; with --png TIME, also a
// still picture of it.

#include <CLI/CLI.hpp>

#include <memory>

namespace graspsim::cli {

class ViewCommand {
public:
    explicit ViewCommand(CLI::App& app);
    bool parsed() const;
    // Writes the page (and the picture); returns 0. Throws InputError for a folder that is not a
    // result of this format or a time outside the run, before writing anything.
    int run() const;

private:
    struct Options;
    std::shared_ptr<Options> options_;
    CLI::App* command_ = nullptr;
};

}  // namespace graspsim::cli
