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
    settings.progress = [&](const RunProgress& p) {
        if (p.finished != kWarmUp) return;
        heapAtWarmUp = graspsim::testing::findLiveHeapBytes();
        residentAtWarmUp = findResidentBytes();
    };
    const RunReport report = runStudyCases(spec, {base}, settings);
    const double heapGrowth = graspsim::testing::findLiveHeapBytes() - heapAtWarmUp;
    const double residentGrowth = findResidentBytes() - residentAtWarmUp;
    EXPECT_EQ(report.total, kCases);
    EXPECT_EQ(report.ran, kCases);
    EXPECT_EQ(report.failed, 2 * kCases / 10);  // case numbers ending in 3 or 7
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

    // Run again: everything is finished, nothing runs.
    settings.progress = {};
    EXPECT_EQ(runStudyCases(spec, {base}, settings).ran, 0);
}
