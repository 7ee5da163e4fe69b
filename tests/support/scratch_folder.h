#pragma once
// A folder of a test's own under the system's temporary folder: made empty before the test,
// removed after it. Its name holds the process id, as ctest runs tests in parallel processes.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace graspsim::testing {

// <tmp>/graspsim_<name>_<pid>, empty (what a killed earlier run left there is removed).
std::filesystem::path makeScratchFolder(const std::string& name);

// A test fixture with such a folder in dir_, named after the test ("Suite_Test", a parameterized
// test's '/' replaced); TearDown removes it. Fixtures that override SetUp or TearDown call these.
class ScratchFolder : public ::testing::Test {
protected:
    void SetUp() override;
    void TearDown() override;

    std::filesystem::path dir_;
};

}  // namespace graspsim::testing
