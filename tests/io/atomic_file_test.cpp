#include "graspsim/io/atomic_file.h"

#include "graspsim/error.h"

#include "scratch_folder.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using namespace graspsim::io;

using graspsim::testing::makeScratchFolder;

TEST(AtomicFile, WritesAndReadsBack) {
    const fs::path dir = makeScratchFolder("write");
    const std::string path = (dir / "out.txt").string();
    writeFileAtomically(path, "hello\n");
    EXPECT_EQ(readTextFile(path), "hello\n");
    writeFileAtomically(path, "replaced");
    EXPECT_EQ(readTextFile(path), "replaced");
    // No temporary file is left beside the result.
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
    fs::remove_all(dir);
}

TEST(AtomicFile, UnwritableFolderLeavesNothingAndNamesThePath) {
    const std::string path = "/nonexistent-graspsim-folder/out.urdf";
    try {
        writeFileAtomically(path, "x");
        FAIL() << "expected InputError";
    } catch (const graspsim::InputError& e) {
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos);
    }
    EXPECT_FALSE(fs::exists(path));
}

TEST(AtomicFile, MissingInputFileIsNamed) {
    EXPECT_THROW(readTextFile("/nonexistent-graspsim-folder/in.urdf"), graspsim::InputError);
    EXPECT_THROW(readTextFile(fs::temp_directory_path().string()), graspsim::InputError);
}
