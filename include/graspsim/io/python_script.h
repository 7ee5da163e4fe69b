#pragma once
/// @file
/// Running one of graspsim's plot scripts (analysis/*.py, compiled into the library) with a
/// Python interpreter that has matplotlib.

#include <string>
#include <vector>

namespace graspsim::io {

/// The Python interpreter used: $GRASPSIM_PYTHON if set, else /usr/bin/python3 (Debian's, which
/// has python3-matplotlib; the python3 first on PATH may be another one without it).
std::string findPythonInterpreter();

/// How a script run ended.
struct ScriptRun {
    std::string command;             ///< the shell command run
    bool started = false;            ///< false: the interpreter is missing or the shell could not start
    int exitStatus = 0;              ///< the script's exit status (when started)
    std::vector<std::string> lines;  ///< its non-empty output lines (stdout, and stderr if asked)
};

/// Writes `text` to `scriptPath` and runs it with findPythonInterpreter() and `arguments`, each
/// passed as one word. With `withStderr` the script's stderr is read with its stdout (to report
/// why it failed).
ScriptRun runPythonScript(const std::string& scriptPath, const std::string& text, const std::vector<std::string>& arguments,
                          bool withStderr);

/// Empty if `run` succeeded; otherwise one line for the user, "plots skipped: WHY; COMPLETE",
/// e.g. "plots skipped: no Python interpreter at /usr/bin/python3 (install python3-matplotlib or
/// set GRASPSIM_PYTHON); results.csv is complete". `script`: its file name, for the message.
std::string explainSkippedPlots(const ScriptRun& run, const std::string& script, const std::string& complete);

}  // namespace graspsim::io
