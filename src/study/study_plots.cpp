#include "graspsim/study/study_plots.h"

#include "embedded_study_scripts.h"

#include "graspsim/io/embedded_file.h"
#include "graspsim/io/python_script.h"

namespace graspsim::study {

PlotOutcome drawStudyPlots(const std::string& folder) {
    PlotOutcome outcome;
    const io::ScriptRun run = io::runPythonScript(
        folder + "/plot_study.py", std::string(io::findEmbeddedFile(kEmbeddedFiles, kEmbeddedFileCount, "plot_study.py")), {folder}, true);
    const std::string python = io::findPythonInterpreter();
    if (!run.started) {
        outcome.skipped = "plots skipped: no Python interpreter at " + python +
                          " (install python3-matplotlib or set GRASPSIM_PYTHON); results.csv is complete";
    } else if (run.exitStatus != 0) {
        outcome.skipped = "plots skipped: " + python + " plot_study.py failed (" + (run.lines.empty() ? "no output" : run.lines.back()) +
                          "; it needs python3-matplotlib); results.csv is complete";
    } else {
        outcome.files = run.lines;
    }
    return outcome;
}

}  // namespace graspsim::study
