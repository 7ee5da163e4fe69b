#include "graspsim/validation/plot_script.h"

#include "embedded_scripts.h"

#include "graspsim/error.h"
#include "graspsim/io/atomic_file.h"
#include "graspsim/io/shell_quote.h"

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>

namespace graspsim::validation {

std::string findPythonInterpreter() {
    const char* python = std::getenv("GRASPSIM_PYTHON");
    return python && *python ? python : "/usr/bin/python3";
}

std::vector<std::string> runPlotScript(const std::string& folder) {
    const std::string script = folder + "/plot_validation.py";
    io::writeFileAtomically(script, std::string(io::findEmbeddedFile(kEmbeddedFiles, kEmbeddedFileCount, "plot_validation.py")));
    const std::string command = io::quoteForShell(findPythonInterpreter()) + " " + io::quoteForShell(script) + " " + io::quoteForShell(folder);
    FILE* pipe = ::popen(command.c_str(), "r");
    if (!pipe) throw Error("cannot start " + command);
    std::vector<std::string> plots;
    std::string line;
    for (int c = std::fgetc(pipe); c != EOF; c = std::fgetc(pipe)) {
        if (c != '\n') { line += static_cast<char>(c); continue; }
        if (!line.empty()) plots.push_back(line);
        line.clear();
    }
    const int status = ::pclose(pipe);
    if (status != 0) {
        throw Error("plotting failed: '" + command + "' exited with status " + std::to_string(WEXITSTATUS(status)) +
                    " (it needs python3-matplotlib; set GRASPSIM_PYTHON to another interpreter)");
    }
    return plots;
}

}  // namespace graspsim::validation
