#pragma once
// `graspsim simulate`: load a scenario, run it, write the result files.

#include "graspsim/capacity/load_direction.h"
#include "graspsim/scenario/scenario.h"
#include "graspsim/simulation/simulation_options.h"

#include <CLI/CLI.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace graspsim::cli {

class SimulateCommand {
public:
    explicit SimulateCommand(CLI::App& app);
    bool parsed() const;
    // Checks the option values that need no scenario (numbers, names); throws InputError.
    void checkOptions() const;
    // Runs the simulation; returns the exit code (0, or 3 when the run stopped early).
    // `commandLine` (argv as given) goes into the result's provenance.json.
    int run(const std::vector<std::string>& commandLine) const;

private:
    // Every option the user gave that needs no scenario, checked before anything is loaded or written.
    simulation::SimulationOptions parseOptions() const;
    // --ramp's direction (none without it), with --ramp-rate and --ramp-torque checked.
    std::optional<capacity::LoadDirection> parseRampDirection() const;
    // The ramp load of --ramp on `scenario`: capacity's load start and (by default) rate.
    // @throws InputError for a torque about a two-finger pinch's axis, which nothing resists.
    simulation::LoadRampSpec makeRamp(const capacity::LoadDirection& direction, const scenario::Scenario& scenario) const;

    struct Options;
    std::shared_ptr<Options> options_;
    CLI::App* command_ = nullptr;
};

}  // namespace graspsim::cli
