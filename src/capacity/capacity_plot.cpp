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
    plot.skipped = io::explainSkippedPlots(run, "plot_capacity.py", "capacity.json and capacity.csv are complete");
    if (plot.skipped.empty()) plot.file = png;
    return plot;
}

}  // namespace graspsim::capacity
