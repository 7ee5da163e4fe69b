#pragma once
/// @file
/// The polar-style plot of `graspsim capacity --direction all --out DIR`: DIR/capacity.png, drawn
/// by analysis/plot_capacity.py (compiled into the library) from DIR/capacity.json: the slip-onset
/// force of the six axis directions on the x-y, y-z and z-x planes of G, and the three torques as
/// bars. The script is left in DIR as plot_capacity.py, to redraw or to overlay several runs
/// (`/usr/bin/python3 DIR/plot_capacity.py OUT.png DIR1 DIR2`).

#include <string>
#include <vector>

namespace graspsim::capacity {

/// What plotting did.
struct CapacityPlot {
    std::string file;     ///< the PNG written (path), or empty
    std::string skipped;  ///< empty, or one line saying why there is no plot
};

/// Draws `folder`/capacity.png from `folder`/capacity.json (writeCapacityFiles). When the
/// interpreter (io::findPythonInterpreter()) is missing or the script fails, says why instead of
/// throwing: capacity.json and capacity.csv stand without the plot.
CapacityPlot drawCapacityPlot(const std::string& folder);

/// Draws `png` from the capacity.json of each of `runFolders`, one curve per folder, labelled with
/// the folder's name (e.g. full contact and approximation variants side by side); the script is
/// left beside `png`. Skips with a reason as above.
CapacityPlot drawCapacityPlot(const std::string& png, const std::vector<std::string>& runFolders);

}  // namespace graspsim::capacity
