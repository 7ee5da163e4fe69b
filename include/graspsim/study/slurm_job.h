#pragma once
/// @file
/// A study as a Slurm job array: an sbatch script whose array task i of K runs
/// `graspsim study run STUDY --out DIR --shard i/K`, and its submission with sbatch.
/// Slurm does the scheduling; `graspsim study collect DIR` merges the shards afterwards.

#include <string>
#include <vector>

namespace graspsim::study {

/// What the script runs.
struct SlurmJob {
    std::string name;        ///< job name (the study's)
    std::string executable;  ///< absolute path of the graspsim binary, as the nodes see it
    std::string studyFile;   ///< absolute path of the study file
    std::string folder;      ///< absolute path of the output folder (shared with the nodes)
    int arraySize = 1;       ///< K tasks, numbered 0..K-1
};

/// The sbatch script: #SBATCH lines for the array and the logs (DIR/slurm/task-<i>.log), then
/// the shard run with $SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT. sbatch's own options
/// (partition, time, account) go on its command line, see submitSlurmJob.
std::string formatSbatchScript(const SlurmJob& job);

/// Runs `sbatch --parsable <sbatchArguments> <scriptPath>` and returns the job id it prints.
/// @throws graspsim::Error with sbatch's message when it is missing or refuses the job.
std::string submitSlurmJob(const std::string& scriptPath, const std::vector<std::string>& sbatchArguments);

}  // namespace graspsim::study
