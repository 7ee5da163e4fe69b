#pragma once
// Runs the real `graspsim` executable in a scratch folder and captures exit code, stdout and
// stderr; shared by the CLI tests.

#include "scratch_folder.h"

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace graspsim::testing {

namespace fs = std::filesystem;


struct RunResult {
    int exitCode = -1;
    std::string out;
    std::string err;
};

inline std::string slurp(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// The captures and the files a test writes go to its scratch folder dir_.
class CliProcess : public ScratchFolder {
protected:
    RunResult run(const std::string& args) const {
        const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
        const std::string command = std::string(GRASPSIM_CLI_PATH) + " " + args + " >" + out.string() + " 2>" + err.string();
        const int status = std::system(command.c_str());
        RunResult r;
        r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        r.out = slurp(out);
        r.err = slurp(err);
        return r;
    }

    // One line naming every expected fragment, exit code 2, and the output file absent.
    void expectBadInput(const std::string& args, std::initializer_list<const char*> fragments) const {
        const RunResult r = run(args);
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        for (const char* f : fragments) EXPECT_NE(r.err.find(f), std::string::npos) << "missing '" << f << "' in: " << r.err;
        EXPECT_FALSE(fs::exists(output())) << args;
        EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 2 + extraFiles_);  // captures
    }

    std::string output() const { return (dir_ / "model.urdf").string(); }
    std::string write(const std::string& name, const std::string& text) const {
        std::ofstream(dir_ / name) << text;
        return (dir_ / name).string();
    }

    int extraFiles_ = 0;  // files a test put in the scratch folder itself
};

}  // namespace graspsim::testing
