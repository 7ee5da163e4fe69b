#include "graspsim/study/study_plots.h"

#include "embedded_study_scripts.h"

#include "graspsim/io/atomic_file.h"
#include "graspsim/io/shell_quote.h"
#include "graspsim/validation/plot_script.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>

namespace graspsim::study {

PlotOutcome drawStudyPlots(const std::string& folder) {
    PlotOutcome outcome;
    const std::string python = validation::findPythonInterpreter();
    if (::access(python.c_str(), X_OK) != 0) {
        outcome.skipped = "plots skipped: no Python interpreter at " + python +
                          " (install python3-matplotlib or set GRASPSIM_PYTHON); results.csv is complete";
        return outcome;
    }
    const std::string script = folder + "/plot_study.py";
    io::writeFileAtomically(script, std::string(io::findEmbeddedFile(kEmbeddedFiles, kEmbeddedFileCount, "plot_study.py")));
    const std::string command = io::quoteForShell(python) + " " + io::quoteForShell(script) + " " + io::quoteForShell(folder) + " 2>&1";
    FILE* pipe = ::popen(command.c_str(), "r");
    if (!pipe) {
        outcome.skipped = "plots skipped: cannot start " + python;
        return outcome;
    }
    std::string line, last;
    std::vector<std::string> lines;
    for (int c = std::fgetc(pipe); c != EOF; c = std::fgetc(pipe)) {
        if (c != '\n') { line += static_cast<char>(c); continue; }
        if (!line.empty()) lines.push_back(line);
        line.clear();
    }
    const int status = ::pclose(pipe);
    if (status != 0) {
        outcome.skipped = "plots skipped: " + python + " plot_study.py failed (" + (lines.empty() ? "no output" : lines.back()) +
                          "; it needs python3-matplotlib); results.csv is complete";
        return outcome;
    }
    outcome.files = lines;
    return outcome;
}

}  // namespace graspsim::study
