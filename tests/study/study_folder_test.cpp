// The study folder: a folder holding another study (or other files) is refused and left as it
// was; a case is committed whole (its temporary folder renamed) and read back.

#include "graspsim/error.h"
#include "graspsim/io/atomic_file.h"
#include "graspsim/study/study_folder.h"

#include "scratch_folder.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <fstream>

using namespace graspsim::study;
namespace fs = std::filesystem;

namespace {

class StudyFolder : public graspsim::testing::ScratchFolder {
protected:
    static StudySpec makeSpec(const std::string& name) {
        return parseStudy("name: " + name + "\nbase: ball-clutch\naxes: {mode: [full]}\nmeasures: [held]\n", "s.yaml");
    }
};

}  // namespace

TEST_F(StudyFolder, SameStudyIsAcceptedAgainAnotherIsRefused) {
    prepareStudyFolder(dir_, makeSpec("a"), "base");
    EXPECT_NO_THROW(prepareStudyFolder(dir_, makeSpec("a"), "base"));
    const std::string before = std::to_string(fs::last_write_time(dir_ / "study.json").time_since_epoch().count());
    try {
        prepareStudyFolder(dir_, makeSpec("b"), "base");
        ADD_FAILURE() << "another study accepted";
    } catch (const graspsim::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("holds the results of another study ('a'"), std::string::npos) << e.what();
    }
    // The same study file on a changed base scenario is another study too.
    EXPECT_THROW(prepareStudyFolder(dir_, makeSpec("a"), "changed base"), graspsim::InputError);
    EXPECT_EQ(std::to_string(fs::last_write_time(dir_ / "study.json").time_since_epoch().count()), before);
    EXPECT_EQ(loadFolderStudy(dir_).name, "a");
}

TEST_F(StudyFolder, FolderWithOtherFilesIsRefused) {
    fs::create_directories(dir_);
    std::ofstream(dir_ / "notes.txt") << "mine";
    EXPECT_THROW(prepareStudyFolder(dir_, makeSpec("a"), "base"), graspsim::InputError);
    EXPECT_FALSE(fs::exists(dir_ / "study.json"));
}

TEST_F(StudyFolder, CaseIsCommittedWholeAndTemporariesRemoved) {
    prepareStudyFolder(dir_, makeSpec("a"), "base");
    const std::string tmp = findCaseFolder(dir_, 3) + ".tmp-1";
    fs::create_directories(tmp);
    fs::create_directories(findCaseFolder(dir_, 3) + ".tmp-2");  // a killed run's leftover
    EXPECT_FALSE(isCaseFinished(dir_, 3));
    commitCase(dir_, tmp, {3, CaseStatus::Failed, "bad \"value\", here", {"x", "[1, 2]"}});
    EXPECT_TRUE(isCaseFinished(dir_, 3));
    EXPECT_FALSE(fs::exists(tmp));
    removeCaseTemporaries(dir_, 3);
    EXPECT_FALSE(fs::exists(findCaseFolder(dir_, 3) + ".tmp-2"));
    const CaseRecord record = readCaseRecord(dir_, 3);
    EXPECT_EQ(record.status, CaseStatus::Failed);
    EXPECT_EQ(record.error, "bad \"value\", here");
    EXPECT_EQ(record.values, (std::vector<std::string>{"x", "[1, 2]"}));
    EXPECT_EQ(findCaseFolder(dir_, 3), (dir_ / "cases/0003").string());
}

// The case's process printed the temporary folder it wrote into; the committed copy names the
// case's folder (stdout.txt, stderr.txt and the error taken from it).
TEST_F(StudyFolder, WhatTheCasePrintedNamesItsCommittedFolder) {
    prepareStudyFolder(dir_, makeSpec("a"), "base");
    const std::string tmp = findCaseFolder(dir_, 1) + ".tmp-6236", target = findCaseFolder(dir_, 1);
    fs::create_directories(tmp);
    std::ofstream(tmp + "/stdout.txt") << "phone-pinch -y force (ramp): slips at 2 N\ncapacity: slips at 2 N; files in " << tmp << "\n";
    std::ofstream(tmp + "/stderr.txt") << "graspsim: cannot write " << tmp << "/capacity.json\n";
    commitCase(dir_, tmp, {1, CaseStatus::Failed, "cannot write " + tmp + "/capacity.json", {"x"}});
    using graspsim::io::readTextFile;
    EXPECT_EQ(readTextFile(target + "/stdout.txt"), "phone-pinch -y force (ramp): slips at 2 N\ncapacity: slips at 2 N; files in " + target + "\n");
    EXPECT_EQ(readTextFile(target + "/stderr.txt"), "graspsim: cannot write " + target + "/capacity.json\n");
    EXPECT_EQ(readCaseRecord(dir_, 1).error, "cannot write " + target + "/capacity.json");
}

// Hand-edited records that are valid JSON of another shape are bad input naming the file, not
// nlohmann's type error escaping as an internal error.
TEST_F(StudyFolder, RecordsOfAnotherShapeAreBadInputNamingTheFile) {
    prepareStudyFolder(dir_, makeSpec("a"), "base");
    const auto expectRefused = [](const std::function<void()>& read, const std::string& fragment) {
        try {
            read();
            ADD_FAILURE() << "accepted; expected " << fragment;
        } catch (const graspsim::InputError& e) {
            EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
        }
    };
    std::ofstream(dir_ / "study.json") << R"({"name": "a", "source": 5})";
    expectRefused([&] { loadFolderStudy(dir_); }, "study.json: field 'source' value '5' is not accepted; it is text");
    std::ofstream(dir_ / "study.json") << "[]";
    expectRefused([&] { loadFolderStudy(dir_); }, "study.json: value '[]' is not accepted; graspsim writes a JSON object here");
    fs::create_directories(findCaseFolder(dir_, 0));
    std::ofstream(findCaseFolder(dir_, 0) + "/case.json") << "[1]";
    expectRefused([&] { readCaseRecord(dir_, 0); }, "cases/0000/case.json: value '[1]' is not accepted");
    std::ofstream(findCaseFolder(dir_, 0) + "/case.json") << R"({"case": "zero"})";
    expectRefused([&] { readCaseRecord(dir_, 0); }, "cases/0000/case.json: is not a graspsim case record");
}
