#include "graspsim/io/python_script.h"

#include "graspsim/io/atomic_file.h"
#include "graspsim/io/shell_quote.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>

namespace graspsim::io {

std::string findPythonInterpreter() {
    const char* python = std::getenv("GRASPSIM_PYTHON");
    return python && *python ? python : "/usr/bin/python3";
}

ScriptRun runPythonScript(const std::string& scriptPath, const std::string& text, const std::vector<std::string>& arguments,
                          bool withStderr) {
    ScriptRun run;
    const std::string python = findPythonInterpreter();
    writeFileAtomically(scriptPath, text);  // kept beside the results, to redraw by hand
    run.command = quoteForShell(python) + " " + quoteForShell(scriptPath);
    for (const std::string& a : arguments) run.command += " " + quoteForShell(a);
    // popen would start a shell that only reports the missing interpreter on stderr.
    if (::access(python.c_str(), X_OK) != 0) return run;
    FILE* pipe = ::popen((run.command + (withStderr ? " 2>&1" : "")).c_str(), "r");
    if (!pipe) return run;
    run.started = true;
    std::string line;
    for (int c = std::fgetc(pipe); c != EOF; c = std::fgetc(pipe)) {
        if (c != '\n') {
            line += static_cast<char>(c);
            continue;
        }
        if (!line.empty()) run.lines.push_back(line);
        line.clear();
    }
    if (!line.empty()) run.lines.push_back(line);
    const int status = ::pclose(pipe);
    run.exitStatus = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
    return run;
}

std::string explainSkippedPlots(const ScriptRun& run, const std::string& script, const std::string& complete) {
    const std::string python = findPythonInterpreter();
    if (!run.started) {
        return "plots skipped: no Python interpreter at " + python + " (install python3-matplotlib or set GRASPSIM_PYTHON); " + complete;
    }
    if (run.exitStatus == 0) return {};
    return "plots skipped: " + python + " " + script + " failed (" + (run.lines.empty() ? "no output" : run.lines.back()) +
           "; it needs python3-matplotlib); " + complete;
}

}  // namespace graspsim::io
