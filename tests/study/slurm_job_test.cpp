// The sbatch script: an array of K tasks, each running its shard with Slurm's task id and count.
// (Submitting it is tested against a real Slurm: tests/cluster.)

#include "graspsim/study/slurm_job.h"

#include <gtest/gtest.h>

using namespace graspsim::study;

TEST(SlurmJob, ScriptRunsShardOfArrayTask) {
    const std::string script = formatSbatchScript({"demo", "/opt/graspsim", "/data/s.yaml", "/data/out dir", 8});
    EXPECT_EQ(script.rfind("#!/bin/bash\n", 0), 0u);
    EXPECT_NE(script.find("#SBATCH --array=0-7\n"), std::string::npos);
    EXPECT_NE(script.find("#SBATCH --output=/data/out dir/slurm/task-%a.log\n"), std::string::npos);
    EXPECT_NE(script.find("exec '/opt/graspsim' study run '/data/s.yaml' --out '/data/out dir' --jobs 1 "
                          "--shard \"${SLURM_ARRAY_TASK_ID}/${SLURM_ARRAY_TASK_COUNT}\"\n"),
              std::string::npos)
        << script;
}
