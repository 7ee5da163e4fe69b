#include "graspsim/capacity/capacity_plot.h"

#include "embedded_capacity_scripts.h"

#include "graspsim/io/embedded_file.h"
#include "graspsim/io/python_script.h"

namespace graspsim::capacity {

CapacityPlot drawCapacityPlot(const std::string& folder) {
    CapacityPlot plot;
    const std::string png = folder + "/capacity.png";
    const io::ScriptRun run = io::runPythonScript(
        folder + "/plot_capacity.py", std::string(io::findEmbeddedFile(kEmbeddedFiles, kEmbeddedFileCount, "plot_capacity.py")),
        {png, folder}, true);
    const std::string python = io::findPythonInterpreter();
    if (!run.started) {
        plot.skipped = "plot skipped: no Python interpreter at " + python +
                       " (install python3-matplotlib or set GRASPSIM_PYTHON); capacity.json and capacity.csv are complete";
    } else if (run.exitStatus != 0) {
        plot.skipped = "plot skipped: " + python + " plot_capacity.py failed (" + (run.lines.empty() ? "no output" : run.lines.back()) +
                       "; it needs python3-matplotlib); capacity.json and capacity.csv are complete";
    } else {
        plot.file = png;
    }
    return plot;
}

}  // namespace graspsim::capacity
