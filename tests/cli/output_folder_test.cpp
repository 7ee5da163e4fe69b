// The --out folder of a run that fails: what the OutputFolder created goes again (leaf first, up
// to the outermost folder it created), what existed before or holds files stays; kept, it stays.
// A folder that cannot be created or refuses files is bad input, and leaves nothing behind.
// Oracle: the file system itself, before and after (and the kernel's refusal of files in /proc).

#include "output_folder.h"

#include "graspsim/error.h"

#include "scratch_folder.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace graspsim::cli {
namespace {

namespace fs = std::filesystem;

using OutputFolderTest = graspsim::testing::ScratchFolder;

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
    EXPECT_THROW(OutputFolder((dir_ / "file").string()), InputError);
}

// Its write test leaves the folder as it found it: empty.
TEST_F(OutputFolderTest, TheWriteTestLeavesNoFile) {
    { OutputFolder folder(dir_.string()); }
    EXPECT_TRUE(fs::is_empty(dir_));
}

// /proc takes no files, whoever asks (root ignores permission bits, so a folder of mode 0555
// would not do): an existing folder that refuses files is refused when the folder is prepared.
TEST_F(OutputFolderTest, AnExistingFolderThatRefusesFilesIsBadInput) {
    if (!fs::is_directory("/proc")) GTEST_SKIP() << "no /proc (not Linux): no folder that refuses files to root";
    try {
        OutputFolder folder("/proc");
        ADD_FAILURE() << "/proc accepted";
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind("--out: folder '/proc' cannot be created or written (", 0), 0u) << message;
        EXPECT_GT(message.size(), std::string("--out: folder '/proc' cannot be created or written ()").size()) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
}

// A name longer than any file system takes (NAME_MAX is 255): the parents are made before the
// leaf fails, and go again.
TEST_F(OutputFolderTest, AFailedCreationRemovesTheParentsItMade) {
    const fs::path path = dir_ / "new" / "parent" / std::string(300, 'n');
    EXPECT_THROW(OutputFolder(path.string()), InputError);
    EXPECT_FALSE(fs::exists(dir_ / "new"));
    EXPECT_TRUE(fs::is_directory(dir_));
}

}  // namespace
}  // namespace graspsim::cli
