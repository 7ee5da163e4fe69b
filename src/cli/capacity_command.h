#pragma once
// `graspsim capacity`: the holding capacity of a scenario's grasp (capacity/grasp_capacity.h).

#include <CLI/CLI.hpp>

#include <memory>

namespace graspsim::cli {

class CapacityCommand {
public:
    explicit CapacityCommand(CLI::App& app);
    bool parsed() const;
    // Checks the option values that need no scenario; throws InputError.
    void checkOptions() const;
    // Measures and writes capacity.json and capacity.csv; returns the exit code (0, or 3 when a
    // run stopped early on a numerical failure: its figures are those up to the failure).
    int run() const;

private:
    struct Options;
    struct Plan;
    Plan makePlan() const;
    std::shared_ptr<Options> options_;
    CLI::App* command_ = nullptr;
};

}  // namespace graspsim::cli
