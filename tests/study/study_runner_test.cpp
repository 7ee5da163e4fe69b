// The runner: every case of the shard gets one process and one committed folder; a process that
// leaves no summary is recorded as failed with its error and the others go on; and over a
// 200-case study the study process's own memory stays flat (the sweep memory test's oracle:
// live heap and resident set at case 200 against case 20). The child here is a /bin/sh script
// that fails or stops early for every fifth case, so the test exercises the runner, not the simulation.

#include "graspsim/study/study_folder.h"
#include "graspsim/study/study_runner.h"

#include "../simulation/live_heap.h"

#include "scratch_folder.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

using namespace graspsim::study;
namespace scenario = graspsim::scenario;
namespace fs = std::filesystem;

namespace {

double findResidentBytes() {
    long pages = 0, resident = 0;
    std::ifstream("/proc/self/statm") >> pages >> resident;
    return static_cast<double>(resident) * static_cast<double>(::sysconf(_SC_PAGESIZE));
}

class StudyRunner : public graspsim::testing::ScratchFolder {
protected:
    void SetUp() override {
        ScratchFolder::SetUp();
        // `simulate SCENARIO --out DIR ...`: writes a summary; fails like graspsim on bad input for
        // cases whose number ends in 3, and stops early (exit 3, incomplete summary) for those
        // ending in 7.
        std::ofstream(dir_ / "fake.sh") << "#!/bin/sh\ncase \"$4\" in *3.tmp-*) echo 'graspsim: case refused' >&2; exit 2;;\n"
                                           "*7.tmp-*) echo '{\"complete\": false, \"failure\": \"diverged\"}' > \"$4/summary.json\"; exit 3;; esac\n"
                                           "echo '{\"held\": true}' > \"$4/summary.json\"\n";
        fs::permissions(dir_ / "fake.sh", fs::perms::owner_all);
    }
};

}  // namespace

TEST_F(StudyRunner, TwoHundredCasesEachCommittedOnceMemoryFlat) {
    constexpr int kCases = 200, kWarmUp = 20;
    const StudySpec spec = parseStudy("name: m\nbase: ball-clutch\naxes: {subject.stature: {from: 1.7, to: 1.8, steps: 200}}\n"
                                      "measures: [held]\n",
                                      (dir_ / "s.yaml").string());
    const scenario::ScenarioText base = scenario::readScenarioText("ball-clutch");
    const std::string folder = (dir_ / "out").string();
    prepareStudyFolder(folder, spec, base.text);
    double heapAtWarmUp = 0, residentAtWarmUp = 0;
    RunSettings settings;
    settings.folder = folder;
    settings.jobs = 2;
    settings.executable = (dir_ / "fake.sh").string();
    RunProgress last;
    settings.progress = [&](const RunProgress& p) {
        last = p;
        if (p.finished != kWarmUp) return;
        heapAtWarmUp = graspsim::testing::findLiveHeapBytes();
        residentAtWarmUp = findResidentBytes();
    };
    const RunReport report = runStudyCases(spec, {base}, settings);
    const double heapGrowth = graspsim::testing::findLiveHeapBytes() - heapAtWarmUp;
    const double residentGrowth = findResidentBytes() - residentAtWarmUp;
    EXPECT_EQ(report.total, kCases);
    EXPECT_EQ(report.ran, kCases);
    // Case numbers ending in 3 fail, those ending in 7 stop early: each counted apart, in the report
    // and in the last progress report alike.
    EXPECT_EQ(report.failed, kCases / 10);
    EXPECT_EQ(report.incomplete, kCases / 10);
    EXPECT_EQ(last.finished, kCases);
    EXPECT_EQ(last.failed, kCases / 10);
    EXPECT_EQ(last.incomplete, kCases / 10);
    EXPECT_EQ(readCaseRecord(folder, 13).error, "case refused");
    EXPECT_EQ(readCaseRecord(folder, 13).status, CaseStatus::Failed);
    EXPECT_EQ(readCaseRecord(folder, 17).error, "diverged");
    EXPECT_EQ(readCaseRecord(folder, 17).status, CaseStatus::Incomplete);
    EXPECT_EQ(readCaseRecord(folder, 14).status, CaseStatus::Ok);
    for (int i = 0; i < kCases; ++i) ASSERT_TRUE(isCaseFinished(folder, i)) << i;
    EXPECT_EQ(std::distance(fs::directory_iterator(folder + "/cases"), fs::directory_iterator()), kCases) << "no temporaries left";
    std::cout << "study process from case " << kWarmUp << " to " << kCases << ": live heap growth " << heapGrowth / 1e3
              << " kB, resident set growth " << residentGrowth / 1e3 << " kB\n";
    EXPECT_LT(heapGrowth, 100e3);  // one case's setup (scenario text, YAML) is ~100 kB
#ifndef GRASPSIM_SANITIZED  // AddressSanitizer keeps freed blocks in quarantine: resident set grows by design
    EXPECT_LT(residentGrowth, 2e6);
#endif

    // Run again: everything is finished, nothing runs; the kept records are counted as they were.
    settings.progress = [&](const RunProgress& p) { last = p; };
    const RunReport again = runStudyCases(spec, {base}, settings);
    EXPECT_EQ(again.ran, 0);
    EXPECT_EQ(again.failed, kCases / 10);
    EXPECT_EQ(again.incomplete, kCases / 10);
    EXPECT_EQ(last.failed, kCases / 10);
    EXPECT_EQ(last.incomplete, kCases / 10);
}

// The terminal's progress line counts incomplete and failed cases apart, in the words of the
// summary ("2 ok, 1 incomplete, 0 failed"); without incomplete cases it reads as it always did.
TEST(StudyRunnerProgress, TheLineCountsIncompleteCasesApartFromFailedOnes) {
    RunProgress p;
    p.finished = 2;
    p.total = 4;
    p.incomplete = 1;
    p.elapsed = 12;
    p.remaining = 12;
    EXPECT_EQ(formatRunProgress(p), "[###############...............] 2/4 cases, 1 incomplete, 0 failed, 0:00:12 elapsed, ETA 0:00:12 ");
    p.finished = 1;
    p.incomplete = 0;
    p.failed = 1;
    p.elapsed = 3725;
    p.remaining = -1;
    EXPECT_EQ(formatRunProgress(p), "[#######.......................] 1/4 cases, 1 failed, 1:02:05 elapsed, ETA -:--:-- ");
}
