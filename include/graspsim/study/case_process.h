#pragma once
/// @file
/// One case's `graspsim simulate` as a child process. A process per case keeps cases apart:
/// a crash or a leak in one run cannot touch the others or the study's own process.

#include <sys/types.h>

#include <string>
#include <vector>

namespace graspsim::study {

/// Starts `executable` with `arguments` (argv[1..]), its standard output and error written to
/// the files `stdoutPath` and `stderrPath`. Returns the child's process id.
/// @throws graspsim::Error when the process cannot be started.
pid_t startCaseProcess(const std::string& executable, const std::vector<std::string>& arguments,
                       const std::string& stdoutPath, const std::string& stderrPath);

/// How a child ended, as waitpid reported it.
struct ProcessEnd {
    pid_t pid = 0;
    int exitCode = -1;  ///< its exit status, or -1 when a signal ended it
    int signal = 0;     ///< the signal that ended it, or 0
};

/// Waits for any of this process's children to end.
/// @throws graspsim::Error when there is no child to wait for.
ProcessEnd waitForAnyChild();

}  // namespace graspsim::study
