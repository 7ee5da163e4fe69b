#include "scratch_folder.h"

#include <unistd.h>

#include <algorithm>

namespace graspsim::testing {

namespace fs = std::filesystem;

fs::path makeScratchFolder(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("graspsim_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

void ScratchFolder::SetUp() {
    const ::testing::TestInfo& test = *::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(test.test_suite_name()) + "_" + test.name();
    std::replace(name.begin(), name.end(), '/', '_');
    dir_ = makeScratchFolder(name);
}

void ScratchFolder::TearDown() { fs::remove_all(dir_); }

}  // namespace graspsim::testing
