// The --out folder of a run that fails: what the OutputFolder created goes again (leaf first, up
// to the outermost folder it created), what existed before or holds files stays; kept, it stays.
// Oracle: the file system itself, before and after.

#include "output_folder.h"

#include "graspsim/error.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace graspsim::cli {
namespace {

namespace fs = std::filesystem;

class OutputFolderTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("graspsim_output_folder_test_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
};

TEST_F(OutputFolderTest, WhatItCreatedGoesAgainUnlessKept) {
    {
        OutputFolder folder((dir_ / "a" / "b" / "c").string());
        EXPECT_TRUE(fs::is_directory(dir_ / "a" / "b" / "c"));
    }
    EXPECT_FALSE(fs::exists(dir_ / "a"));
    EXPECT_TRUE(fs::is_directory(dir_)) << "it existed before";
    {
        OutputFolder folder((dir_ / "kept" / "").string());  // a trailing separator names the same folder
        folder.keep();
    }
    EXPECT_TRUE(fs::is_directory(dir_ / "kept"));
}

TEST_F(OutputFolderTest, AFolderThatExistedOrHoldsFilesStays) {
    fs::create_directories(dir_ / "old");
    { OutputFolder folder((dir_ / "old").string()); }
    EXPECT_TRUE(fs::is_directory(dir_ / "old"));
    {
        OutputFolder folder((dir_ / "new" / "run").string());
        std::ofstream(dir_ / "new" / "run" / "partial.csv") << "t\n";
    }
    EXPECT_TRUE(fs::exists(dir_ / "new" / "run" / "partial.csv"));
}

TEST_F(OutputFolderTest, AnUnwritablePathIsBadInput) {
    std::ofstream(dir_ / "file") << "x";
    EXPECT_THROW(OutputFolder((dir_ / "file" / "out").string()), InputError);
}

}  // namespace
}  // namespace graspsim::cli
