#include "graspsim/io/filtered_stderr.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <sys/stat.h>

#include <cstdio>
#include <memory>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace graspsim::io {
namespace {

const std::string kCpodesBlock = "\n[CPODES ERROR]  CPode\n  At t = 0.549816repeated recoverable ODE function errors.\n\n";

TEST(FilterBlocks, DropsOnlyTheBlocksWithAGivenPrefixAndKeepsTheOrder) {
    std::string dropped;
    const std::string text = "first line\n\n" + kCpodesBlock + "second\nthird\n";

    const std::string kept = filterBlocks(text, {"[CPODES ERROR]", "[CPODES WARNING]"}, dropped);

    EXPECT_EQ(kept, "first line\n\nsecond\nthird\n");
    EXPECT_EQ(dropped, kCpodesBlock);
}

TEST(FilterBlocks, KeepsEverythingWithoutAMatchAndHandlesEmptyText) {
    std::string dropped;
    EXPECT_EQ(filterBlocks("a\n\n\nb", {"[CPODES ERROR]"}, dropped), "a\n\n\nb");
    EXPECT_EQ(filterBlocks("", {"[CPODES ERROR]"}, dropped), "");
    EXPECT_EQ(dropped, "");
}

// The scope on the process's fd 2, whose text gtest captures. Sanitizer builds leave stderr alone
// (io/filtered_stderr.h): there is nothing to test.
class FilteredStderrOnFd2 : public ::testing::Test {
protected:
    void SetUp() override {
#ifdef GRASPSIM_SANITIZED
        GTEST_SKIP() << "sanitizer builds leave stderr alone (io/filtered_stderr.h)";
#endif
        testing::internal::CaptureStderr();
    }
};

// End to end on fd 2: what C code prints inside the scope reaches stderr without the dropped block.
TEST_F(FilteredStderrOnFd2, PassesOnWhatIsKeptWhenReleased) {
    std::string dropped;
    {
        FilteredStderr filter({"[CPODES ERROR]"});
        std::fprintf(stderr, "%s", kCpodesBlock.c_str());
        std::fprintf(stderr, "graspsim: kept\n");
        filter.release();
        dropped = filter.getDropped();
    }
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "graspsim: kept\n");
    EXPECT_EQ(dropped, kCpodesBlock);
}

// A long-lived filter (as the CPodes stepper holds one): forward() passes each batch on at once,
// without its dropped blocks, and the scratch file starts empty for the next batch.
TEST_F(FilteredStderrOnFd2, ForwardPassesOnEachBatchAndStaysRedirected) {
    std::string dropped;
    {
        FilteredStderr filter({"[CPODES ERROR]"});
        std::fprintf(stderr, "first\n\n");
        std::fprintf(stderr, "%s", kCpodesBlock.c_str());
        filter.forward();
        filter.forward();  // nothing new: nothing passed on twice
        std::fprintf(stderr, "%s", kCpodesBlock.c_str());
        std::fprintf(stderr, "second\n");
        filter.forward();
        dropped = filter.getDropped();
    }
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "first\n\nsecond\n");
    EXPECT_EQ(dropped, kCpodesBlock + kCpodesBlock);
}

// Overlapping instances (capacity --jobs runs CPodes steppers at once, each holding one): they
// share one redirection, so the first to end leaves fd 2 redirected for the other, the last
// restores it, and nothing is lost or passed on twice. Oracle: fd 2's file (device and inode)
// before and after, and the captured text.
TEST_F(FilteredStderrOnFd2, OverlappingInstancesShareOneRedirection) {
    const auto identify = [] {
        struct stat s {};
        ::fstat(2, &s);
        return std::pair{s.st_dev, s.st_ino};
    };
    const auto before = identify();
    std::string dropped;
    {
        auto first = std::make_unique<FilteredStderr>(std::vector<std::string>{"[CPODES ERROR]"});
        FilteredStderr second({"[CPODES ERROR]"});
        std::fprintf(stderr, "one\n\n");
        std::fprintf(stderr, "%s", kCpodesBlock.c_str());
        first.reset();  // the first ends while the second lives: fd 2 stays redirected
        EXPECT_NE(identify(), before);
        std::fprintf(stderr, "%s", kCpodesBlock.c_str());
        std::fprintf(stderr, "two\n");
        second.release();
        dropped = second.getDropped();
        EXPECT_EQ(identify(), before);
    }
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "one\n\ntwo\n");
    EXPECT_EQ(dropped, kCpodesBlock);  // the first's block was the first's
}

// A write that lands past the scratch file's end (another thread's, racing the file's reset; here
// made by moving the offset fd 2 shares) leaves a hole of zero bytes before its text. The hole is
// not stderr text: the block after it is still recognized and dropped, and nothing is passed on.
TEST_F(FilteredStderrOnFd2, AHoleBeforeABlockIsNotText) {
    std::string dropped;
    {
        FilteredStderr filter({"[CPODES ERROR]"});
        ASSERT_GT(::lseek(2, 64, SEEK_CUR), 0);
        std::fprintf(stderr, "%s", kCpodesBlock.c_str());
        filter.forward();
        std::fprintf(stderr, "kept\n");
        filter.release();
        dropped = filter.getDropped();
    }
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "kept\n");
    EXPECT_EQ(dropped, kCpodesBlock);
}

// Many threads, each with its own instance for a while: fd 2 is the original at the end.
TEST_F(FilteredStderrOnFd2, ThreadsLeaveStderrAsTheyFoundIt) {
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t) {
        threads.emplace_back([] {
            for (int k = 0; k < 50; ++k) {
                FilteredStderr filter({"[CPODES ERROR]"});
                std::fprintf(stderr, "%s", kCpodesBlock.c_str());
                filter.forward();
            }
        });
    }
    for (std::thread& t : threads) t.join();
    std::fprintf(stderr, "after\n");
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "after\n");
}

}  // namespace
}  // namespace graspsim::io
