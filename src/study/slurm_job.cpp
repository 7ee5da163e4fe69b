#include "graspsim/study/slurm_job.h"

#include "graspsim/error.h"
#include "graspsim/io/shell_quote.h"

#include <sys/wait.h>

#include <cstdio>
#include <sstream>

namespace graspsim::study {

std::string formatSbatchScript(const SlurmJob& job) {
    std::ostringstream s;
    s << "#!/bin/bash\n"
      << "# graspsim study '" << job.name << "' as a Slurm job array: task i of K runs shard i/K of the cases.\n"
      << "# Written by `graspsim study submit`; merge the shards with `graspsim study collect " << job.folder << "`.\n"
      << "#SBATCH --job-name=graspsim-" << job.name << "\n"
      << "#SBATCH --array=0-" << job.arraySize - 1 << "\n"
      << "#SBATCH --ntasks=1\n"
      << "#SBATCH --cpus-per-task=1\n"
      << "#SBATCH --output=" << job.folder << "/slurm/task-%a.log\n"
      << "set -euo pipefail\n"
      << "exec " << io::quoteForShell(job.executable) << " study run " << io::quoteForShell(job.studyFile) << " --out "
      << io::quoteForShell(job.folder) << " --jobs 1 --shard \"${SLURM_ARRAY_TASK_ID}/${SLURM_ARRAY_TASK_COUNT}\"\n";
    return s.str();
}

std::string submitSlurmJob(const std::string& scriptPath, const std::vector<std::string>& sbatchArguments) {
    std::string command = "sbatch --parsable";
    for (const std::string& argument : sbatchArguments) command += " " + io::quoteForShell(argument);
    command += " " + io::quoteForShell(scriptPath) + " 2>&1";
    FILE* pipe = ::popen(command.c_str(), "r");
    if (!pipe) throw Error("cannot start sbatch");
    std::string output;
    for (int c = std::fgetc(pipe); c != EOF; c = std::fgetc(pipe)) output += static_cast<char>(c);
    const int status = ::pclose(pipe);
    while (!output.empty() && (output.back() == '\n' || output.back() == '\r')) output.pop_back();
    // Both are the user's to fix (a machine without Slurm, an sbatch option the site refuses).
    if (WIFEXITED(status) && WEXITSTATUS(status) == 127) {
        throw InputError("sbatch is not found; submit from a machine with Slurm's client, or run the shards with "
                         "`graspsim study run STUDY --out DIR --shard i/K`");
    }
    if (status != 0) throw InputError("sbatch refused the job (" + command + "): " + foldToOneLine(output));
    const std::size_t lastLine = output.find_last_of('\n');
    std::string id = lastLine == std::string::npos ? output : output.substr(lastLine + 1);
    return id.substr(0, id.find(';'));  // --parsable prints "id" or "id;cluster"
}

}  // namespace graspsim::study
