#include "graspsim/validation/plot_script.h"

#include "embedded_scripts.h"

#include "graspsim/error.h"
#include "graspsim/io/embedded_file.h"
#include "graspsim/io/python_script.h"

namespace graspsim::validation {

std::vector<std::string> runPlotScript(const std::string& folder) {
    const io::ScriptRun run =
        io::runPythonScript(folder + "/plot_validation.py",
                            std::string(io::findEmbeddedFile(kEmbeddedFiles, kEmbeddedFileCount, "plot_validation.py")), {folder}, false);
    if (!run.started) {
        throw Error("plotting failed: cannot run '" + run.command +
                    "' (install python3-matplotlib or set GRASPSIM_PYTHON; --no-plots skips the plots)");
    }
    if (run.exitStatus != 0) {
        throw Error("plotting failed: '" + run.command + "' exited with status " + std::to_string(run.exitStatus) +
                    " (it needs python3-matplotlib; set GRASPSIM_PYTHON to another interpreter)");
    }
    return run.lines;
}

}  // namespace graspsim::validation
