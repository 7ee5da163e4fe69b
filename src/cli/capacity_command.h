#pragma once
// `graspsim capacity`: the holding capacity of a scenario's grasp (capacity/grasp_capacity.h).

#include <CLI/CLI.hpp>

#include "graspsim/capacity/grasp_capacity.h"
#include "graspsim/scenario/scenario.h"

#include <memory>
#include <vector>

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
    // Every request of `plan`, --jobs at a time, each line printed as it and those before it end.
    std::vector<capacity::GraspCapacity> measureAll(const scenario::Scenario& scenario, const Plan& plan) const;
    std::shared_ptr<Options> options_;
    CLI::App* command_ = nullptr;
};

}  // namespace graspsim::cli
