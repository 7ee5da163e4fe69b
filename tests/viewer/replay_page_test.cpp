// A short approx run of the phone pinch (approach and settling shortened so the approximation
// engages, at about 0.22 s) written as a result folder, read back by the viewer, and turned into the
// replay's data. Oracles: the run's own result (samples, joint angles, constraint samples read back
// exactly), physics (contact forces push into the object along the normal; the constraint's reaction stays within
// its friction limits), and the reader's refusal of folders that are not results of this format.

#include "graspsim/error.h"
#include "graspsim/results/result_folder.h"
#include "graspsim/scenario/scenario_file.h"
#include "graspsim/simulation/grasp_simulation.h"
#include "graspsim/viewer/replay_page.h"
#include "graspsim/viewer/result_reader.h"

#include "scratch_folder.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace graspsim::viewer {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

scenario::Scenario makeShortPhoneScenario() {
    std::string text = slurp(fs::path(GRASPSIM_SOURCE_DIR) / "models/scenarios/phone-pinch.yaml");
    for (const auto& [from, to] : {std::pair<std::string, std::string>{"approach_time: 0.5 ", "approach_time: 0.05"},
                                   {"settle_time: 1.0 ", "settle_time: 0.15"}}) {
        const std::size_t at = text.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        text.replace(at, from.size(), to);
    }
    return scenario::parseScenario(text, "short-phone.yaml");
}

class ReplayPage : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        folder_ = new fs::path(graspsim::testing::makeScratchFolder("replay"));
        scenario_ = new scenario::Scenario(makeShortPhoneScenario());
        simulation::SimulationOptions options;
        options.mode = simulation::SimulationMode::Approx;
        options.duration = 0.4;
        result_ = new simulation::SimulationResult(simulation::runGraspSimulation(*scenario_, options));
        results::writeResultFolder(folder_->string(), *scenario_, *result_, {{"graspsim", "simulate"}, {{"mode", "approx"}}});
    }
    static void TearDownTestSuite() {
        fs::remove_all(*folder_);
        delete folder_;
        delete result_;
        delete scenario_;
    }
    // A copy of the result folder to break.
    fs::path copyFolder(const std::string& name) const {
        const fs::path copy = *folder_ / ".." / (folder_->filename().string() + "_" + name);
        fs::remove_all(copy);
        fs::copy(*folder_, copy);
        copies_.push_back(copy);
        return copy;
    }
    void TearDown() override {
        for (const fs::path& p : copies_) fs::remove_all(p);
    }
    // Replaces the time of the `index`-th sample (0: the first data line) of the folder's trajectory.
    static void replaceTrajectoryTime(const fs::path& folder, std::size_t index, const std::string& time) {
        std::ifstream in(folder / "trajectory.csv");
        std::vector<std::string> lines;
        for (std::string line; std::getline(in, line);) lines.push_back(line);
        in.close();
        std::string& line = lines.at(index + 1);
        line = time + line.substr(line.find(','));
        std::ofstream out(folder / "trajectory.csv");
        for (const std::string& l : lines) out << l << "\n";
    }
    void expectRejected(const fs::path& folder, const std::string& fragment) const {
        try {
            readResultFolder(folder.string());
            ADD_FAILURE() << "accepted " << folder;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
            EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
        }
    }

    static fs::path* folder_;
    static scenario::Scenario* scenario_;
    static simulation::SimulationResult* result_;
    mutable std::vector<fs::path> copies_;
};
fs::path* ReplayPage::folder_ = nullptr;
scenario::Scenario* ReplayPage::scenario_ = nullptr;
simulation::SimulationResult* ReplayPage::result_ = nullptr;

TEST_F(ReplayPage, ResultFolderReadsBackTheRun) {
    const ResultRecord record = readResultFolder(folder_->string());
    ASSERT_EQ(record.trajectory.size(), result_->trajectory.size());
    EXPECT_EQ(record.mode, simulation::SimulationMode::Approx);
    EXPECT_EQ(record.scenario.controller.approachTime, scenario_->controller.approachTime);
    for (std::size_t i = 0; i < record.trajectory.size(); ++i) {
        EXPECT_EQ(record.trajectory[i].time, result_->trajectory[i].time);
        for (std::size_t j = 0; j < result_->jointNames.size(); ++j) {
            EXPECT_EQ(record.trajectory[i].jointAngles.at(result_->jointNames[j]), result_->trajectory[i].jointAngles[j]);
        }
    }
    ASSERT_GT(result_->constraint.size(), 0u) << "the approximation never engaged";
    ASSERT_EQ(record.constraint.size(), result_->constraint.size());
    for (std::size_t i = 0; i < record.constraint.size(); ++i) {
        for (int k = 0; k < 6; ++k) EXPECT_EQ(record.constraint[i].reaction[k], result_->constraint[i].reaction[k]);
    }
    const nlohmann::json provenance = nlohmann::json::parse(slurp(*folder_ / "provenance.json"));
    EXPECT_EQ(provenance["format"], results::kResultFormat);
    EXPECT_EQ(provenance["command_line"][1], "simulate");
}

TEST_F(ReplayPage, ConstraintReactionStaysWithinItsLimits) {
    for (const simulation::ConstraintSample& c : result_->constraint) {
        for (int k = 0; k < 6; ++k) {
            if (!std::isfinite(c.limits[k])) continue;
            EXPECT_LE(std::abs(c.reaction[k]), c.limits[k] * (1 + 1e-6) + 1e-9) << "axis " << k << " at t = " << c.time;
        }
    }
}

// A folder written before the object was "object" in every scenario (the phone was body "phone",
// geometry "phone_box") replays the same: the object is the side that is not a body of model.urdf.
TEST_F(ReplayPage, ContactsOfAnObjectNamedOtherwiseShowTheSameArrows) {
    const ResultRecord record = readResultFolder(folder_->string());
    ResultRecord renamed = record;
    std::size_t onObject = 0;
    for (ContactRow& k : renamed.contacts) {
        if (k.bodyB != "object") continue;
        k.bodyB = "phone";
        ++onObject;
    }
    ASSERT_GT(onObject, 0u);
    const nlohmann::json data = nlohmann::json::parse(formatReplayJson(record));
    EXPECT_EQ(nlohmann::json::parse(formatReplayJson(renamed))["contacts"], data["contacts"]);
}

TEST_F(ReplayPage, DataHoldsEverySampleWithPosesForcesAndEngagement) {
    const ResultRecord record = readResultFolder(folder_->string());
    const nlohmann::json data = nlohmann::json::parse(formatReplayJson(record));
    const std::size_t frames = record.trajectory.size();
    ASSERT_EQ(data["times"].size(), frames);
    std::size_t withGeometry = 0;
    for (const model::Body& b : record.model.bodies) withGeometry += b.geometry.empty() ? 0 : 1;
    ASSERT_EQ(data["bodies"].size(), withGeometry + 1);  // and the object, last
    EXPECT_EQ(data["bodies"].back()["name"], "object");
    for (std::size_t f = 0; f < frames; ++f) {
        const nlohmann::json& pose = data["poses"][f];
        ASSERT_EQ(pose.size(), 7 * data["bodies"].size());
        const std::size_t o = pose.size() - 7;
        const model::Vec3& p_GO = record.trajectory[f].p_GO;
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(pose[o + k].get<double>(), p_GO[k], 1e-6);
        // Every contact pushes the object (a unilateral contact): the arrow's force has the normal
        // force as its component along the normal into the object, friction being tangential.
        const nlohmann::json& contacts = data["contacts"][f];
        ASSERT_EQ(contacts.size(), result_->contacts[f].contacts.size());
        for (std::size_t i = 0; i < contacts.size(); ++i) {
            const contact::ContactReport& c = result_->contacts[f].contacts[i];
            const double intoObject = c.bodyB == "object" ? 1.0 : -1.0;  // n_G points from a to b
            double along = 0;
            for (int k = 0; k < 3; ++k) along += contacts[i][3 + k].get<double>() * intoObject * c.n_G[k];
            EXPECT_NEAR(along, c.normalForce, 1e-5 * (1 + c.normalForce)) << "t = " << record.trajectory[f].time;
            EXPECT_GE(along, 0);
        }
        // A constraint sample exactly while engaged (the switch instants themselves may fall either side).
        const double t = record.trajectory[f].time;
        bool atSwitch = false, engaged = false;
        for (const simulation::GraspEvent& e : result_->events) {
            if (std::abs(t - e.time) < 1e-9) atSwitch = true;
            if (e.time < t && e.kind != simulation::GraspEventKind::Detach) engaged = e.kind == simulation::GraspEventKind::Engage;
        }
        if (!atSwitch) {
            EXPECT_EQ(!data["constraintSamples"][f].is_null(), engaged) << "t = " << t;
        }
    }
    ASSERT_GE(data["engaged"].size(), 1u);
    EXPECT_EQ(data["engaged"][0][0].get<double>(), result_->summary.engageTime);
}

// A run that stopped early carries its failure to the page; a complete one has none.
TEST_F(ReplayPage, AnIncompleteRunSaysWhyItStopped) {
    ResultRecord record = readResultFolder(folder_->string());
    EXPECT_FALSE(nlohmann::json::parse(formatReplayJson(record)).contains("failure"));
    nlohmann::json summary = nlohmann::json::parse(record.summaryJson);
    summary["complete"] = false;
    summary["failure"] = "the integrator stalled at t = 0.2 s";
    record.summaryJson = summary.dump();
    EXPECT_EQ(nlohmann::json::parse(formatReplayJson(record))["failure"], "the integrator stalled at t = 0.2 s");
}

TEST_F(ReplayPage, PageIsSelfContained) {
    const std::string page = makeReplayPage(readResultFolder(folder_->string()));
    EXPECT_NE(page.find("THREE"), std::string::npos);
    EXPECT_NE(page.find("OrbitControls"), std::string::npos);
    EXPECT_EQ(page.find("/*GRASPSIM_"), std::string::npos) << "a placeholder is left";
    // No resource is fetched: no src= or href= to anything outside the page.
    EXPECT_EQ(page.find("<script src"), std::string::npos);
    EXPECT_EQ(page.find("<link "), std::string::npos);
}

TEST_F(ReplayPage, RefusesWhatIsNotAResultOfThisFormat) {
    expectRejected(*folder_ / "trajectory.csv", "is not a folder");
    const fs::path empty = copyFolder("empty");
    for (const auto& entry : fs::directory_iterator(empty)) fs::remove(entry.path());
    expectRejected(empty, "is not a graspsim result folder");
    const fs::path old = copyFolder("old");
    fs::remove(old / "provenance.json");
    expectRejected(old, "older graspsim");
    const fs::path future = copyFolder("future");
    std::ofstream(future / "provenance.json") << R"({"format": 2})";
    expectRejected(future, "result format 2 is not supported");
    // Valid JSON of another shape is bad input too, not an internal error.
    const fs::path list = copyFolder("list");
    std::ofstream(list / "provenance.json") << "[]";
    expectRejected(list, "provenance.json: value '[]' is not accepted; a graspsim provenance.json is a JSON object");
    const fs::path text = copyFolder("text");
    std::ofstream(text / "provenance.json") << R"({"format": "one"})";
    expectRejected(text, "provenance.json: field 'format' value '\"one\"' is not accepted");
    const fs::path noModel = copyFolder("nomodel");
    fs::remove(noModel / "model.urdf");
    expectRejected(noModel, "model.urdf is missing");
    const fs::path badColumns = copyFolder("columns");
    std::ofstream(badColumns / "trajectory.csv") << "time,x\n0,1\n";
    expectRejected(badColumns, "trajectory.csv: columns are not graspsim's");
    // A sample time that is not a finite number, or goes back, would replay nonsense.
    const fs::path nanTime = copyFolder("nantime");
    replaceTrajectoryTime(nanTime, 2, "nan");
    expectRejected(nanTime, "trajectory.csv:4: field 'time_s' value 'nan' is not accepted; sample times are finite and in increasing order");
    const fs::path backTime = copyFolder("backtime");
    replaceTrajectoryTime(backTime, 3, "0");
    expectRejected(backTime, "trajectory.csv:5: field 'time_s' value '0' is not accepted");
    const fs::path noConstraint = copyFolder("noconstraint");
    fs::remove(noConstraint / "constraint.csv");
    expectRejected(noConstraint, "constraint.csv is missing");
}

}  // namespace
}  // namespace graspsim::viewer
