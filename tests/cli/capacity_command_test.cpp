#include "cli_process.h"

using graspsim::testing::CliProcess;
using graspsim::testing::RunResult;
using graspsim::testing::slurp;
namespace fs = std::filesystem;

namespace {

class CapacityCommand : public CliProcess {
protected:
    // Bad input: one line naming the flag, exit 2, and no output folder created.
    void expectRejected(const std::string& args, const char* flag) {
        const std::string out = (dir_ / "cap").string();
        const RunResult r = run("capacity phone-pinch " + args + " --out " + out);
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_NE(r.err.find(flag), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(out)) << args;
    }
};

}  // namespace

TEST_F(CapacityCommand, BadInputIsOneLineAndWritesNothing) {
    expectRejected("--direction 0,0,0", "--direction");
    expectRejected("--direction nan,1,0", "--direction");
    expectRejected("--direction up", "--direction");
    expectRejected("--direction 1,2", "--direction");
    expectRejected("--rate 0", "--rate");
    expectRejected("--rate=-3", "--rate");
    expectRejected("--rate inf", "--rate");
    expectRejected("--method guess", "--method");
    expectRejected("--mode half", "--mode");
}
