#include "graspsim/study/study_plots.h"

#include "embedded_study_scripts.h"

#include "graspsim/io/embedded_file.h"
#include "graspsim/io/python_script.h"

namespace graspsim::study {

PlotOutcome drawStudyPlots(const std::string& folder) {
    PlotOutcome outcome;
    const io::ScriptRun run = io::runPythonScript(
        folder + "/plot_study.py", std::string(io::findEmbeddedFile(kEmbeddedFiles, kEmbeddedFileCount, "plot_study.py")), {folder}, true);
    outcome.skipped = io::explainSkippedPlots(run, "plot_study.py", "results.csv is complete");
    if (outcome.skipped.empty()) outcome.files = run.lines;
    return outcome;
}

}  // namespace graspsim::study
