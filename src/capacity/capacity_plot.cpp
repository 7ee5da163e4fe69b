#include "graspsim/capacity/capacity_plot.h"

#include "embedded_capacity_scripts.h"

#include "graspsim/io/embedded_file.h"
#include "graspsim/io/python_script.h"

#include <filesystem>

namespace graspsim::capacity {

CapacityPlot drawCapacityPlot(const std::string& folder) { return drawCapacityPlot(folder + "/capacity.png", {folder}); }

CapacityPlot drawCapacityPlot(const std::string& png, const std::vector<std::string>& runFolders) {
    CapacityPlot plot;
    const std::string script = std::filesystem::path(png).replace_filename("plot_capacity.py").string();
    std::vector<std::string> arguments{png};
    arguments.insert(arguments.end(), runFolders.begin(), runFolders.end());
    const io::ScriptRun run = io::runPythonScript(
        script, std::string(io::findEmbeddedFile(kEmbeddedFiles, kEmbeddedFileCount, "plot_capacity.py")), arguments, true);
    plot.skipped = io::explainSkippedPlots(run, "plot_capacity.py", "the capacity tables are complete");
    if (plot.skipped.empty()) plot.file = png;
    return plot;
}

}  // namespace graspsim::capacity
