#include "graspsim/study/study_runner.h"

#include "graspsim/error.h"
#include "graspsim/io/atomic_file.h"
#include "graspsim/study/case_process.h"
#include "graspsim/study/case_setup.h"
#include "graspsim/study/study_folder.h"
#include "graspsim/study/study_table.h"

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <map>

namespace graspsim::study {

namespace fs = std::filesystem;

namespace {

// A case whose process is running.
struct RunningCase {
    StudyCase studyCase;
    std::string tmpFolder;
};

// The last non-empty line of a file, without graspsim's "graspsim: " prefix.
std::string findLastLine(const std::string& path) {
    std::string text;
    try {
        text = io::readTextFile(path);
    } catch (const InputError&) {
        return "";
    }
    std::string last, line;
    for (char c : text + "\n") {
        if (c != '\n' && c != '\r') { line += c; continue; }
        if (!line.empty()) last = line;
        line.clear();
    }
    const std::string prefix = "graspsim: ";
    return last.rfind(prefix, 0) == 0 ? last.substr(prefix.size()) : last;
}

// Why a run that wrote its results stopped early: summary.json's "failure", or capacity.json's
// measurement's.
std::string findFailure(const std::string& path, StudyCommand command) {
    try {
        nlohmann::json json = nlohmann::json::parse(io::readTextFile(path));
        if (command == StudyCommand::Capacity) json = json.at("measurements").at(0);
        return json.value("failure", "stopped early");
    } catch (const nlohmann::json::exception&) {
        return "stopped early; " + fs::path(path).filename().string() + " unreadable";
    }
}

// The case's status from how its process ended and what it wrote.
CaseRecord judgeCase(const RunningCase& running, const ProcessEnd& end, StudyCommand command) {
    CaseRecord record{running.studyCase.index, CaseStatus::Failed, "", running.studyCase.values};
    const std::string summaryPath = running.tmpFolder + "/" + nameResultFile(command);
    const bool hasSummary = fs::is_regular_file(summaryPath);
    if (end.exitCode == 0 && hasSummary) {
        record.status = CaseStatus::Ok;
    } else if (end.exitCode == 3 && hasSummary) {
        record.status = CaseStatus::Incomplete;
        record.error = findFailure(summaryPath, command);
    } else {
        record.error = findLastLine(running.tmpFolder + "/stderr.txt");
        if (record.error.empty()) {
            record.error = end.signal ? "killed by signal " + std::to_string(end.signal) : "exit status " + std::to_string(end.exitCode);
        }
    }
    return record;
}

class CaseScheduler {
public:
    CaseScheduler(const StudySpec& spec, const std::vector<scenario::ScenarioText>& bases, const RunSettings& settings)
        : spec_(spec), bases_(bases), settings_(settings), start_(std::chrono::steady_clock::now()) {}

    RunReport run() {
        queueCases();
        report();
        while (!pending_.empty() || !running_.empty()) {
            while (static_cast<int>(running_.size()) < settings_.jobs && !pending_.empty()) {
                startCase(pending_.front());
                pending_.pop_front();
            }
            if (!running_.empty()) finishCase(waitForAnyChild());
        }
        return report_;
    }

private:
    void queueCases() {
        for (const StudyCase& c : selectShard(expandCases(spec_), settings_.shard)) {
            ++report_.total;
            if (isCaseFinished(settings_.folder, c.index)) {
                const CaseStatus status = readCaseRecord(settings_.folder, c.index).status;
                if (status == CaseStatus::Ok || !settings_.retryFailed) {
                    ++report_.skipped;
                    countNotOk(status);
                    continue;
                }
                fs::remove_all(findCaseFolder(settings_.folder, c.index));
            }
            removeCaseTemporaries(settings_.folder, c.index);
            pending_.push_back(c);
        }
    }

    // A case whose parameters the reader refuses is recorded without a process.
    void startCase(const StudyCase& studyCase) {
        const std::string tmp = findCaseFolder(settings_.folder, studyCase.index) + ".tmp-" + std::to_string(::getpid());
        fs::create_directories(tmp);
        CaseSetup setup;
        try {
            setup = makeCaseSetup(spec_, bases_, studyCase);
        } catch (const InputError& e) {
            record(tmp, {studyCase.index, CaseStatus::Failed, e.what(), studyCase.values});
            return;
        }
        io::writeFileAtomically(tmp + "/scenario.yaml", setup.scenarioYaml);
        std::vector<std::string> arguments{toString(spec_.command), tmp + "/scenario.yaml", "--out", tmp};
        for (const auto& [option, value] : setup.options) {
            arguments.push_back(option);
            if (!value.empty()) arguments.push_back(value);
        }
        const pid_t pid = startCaseProcess(settings_.executable, arguments, tmp + "/stdout.txt", tmp + "/stderr.txt");
        running_[pid] = {studyCase, tmp};
    }

    void finishCase(const ProcessEnd& end) {
        const auto it = running_.find(end.pid);
        if (it == running_.end()) return;  // not one of ours
        const RunningCase running = it->second;
        running_.erase(it);
        record(running.tmpFolder, judgeCase(running, end, spec_.command));
    }

    void record(const std::string& tmp, const CaseRecord& caseRecord) {
        commitCase(settings_.folder, tmp, caseRecord);
        ++report_.ran;
        countNotOk(caseRecord.status);
        report();
    }

    void countNotOk(CaseStatus status) {
        if (status == CaseStatus::Incomplete) ++report_.incomplete;
        if (status == CaseStatus::Failed) ++report_.failed;
    }

    void report() const {
        if (!settings_.progress) return;
        RunProgress progress;
        progress.finished = report_.skipped + report_.ran;
        progress.total = report_.total;
        progress.incomplete = report_.incomplete;
        progress.failed = report_.failed;
        progress.elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        if (report_.ran > 0) progress.remaining = progress.elapsed / report_.ran * (report_.total - progress.finished);
        settings_.progress(progress);
    }

    const StudySpec& spec_;
    const std::vector<scenario::ScenarioText>& bases_;
    const RunSettings& settings_;
    const std::chrono::steady_clock::time_point start_;
    std::deque<StudyCase> pending_;
    std::map<pid_t, RunningCase> running_;
    RunReport report_;
};

std::string formatClock(double seconds) {
    const long s = static_cast<long>(seconds + 0.5);
    char text[32];
    std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
    return text;
}

}  // namespace

std::string formatRunProgress(const RunProgress& p) {
    constexpr int kWidth = 30;
    const int filled = p.total ? kWidth * p.finished / p.total : kWidth;
    return "[" + std::string(filled, '#') + std::string(kWidth - filled, '.') + "] " + std::to_string(p.finished) + "/" +
           std::to_string(p.total) + " cases, " + formatFailureCounts(p.incomplete, p.failed) + ", " + formatClock(p.elapsed) +
           " elapsed, ETA " + (p.remaining < 0 ? "-:--:--" : formatClock(p.remaining)) + " ";
}

RunReport runStudyCases(const StudySpec& spec, const std::vector<scenario::ScenarioText>& bases, const RunSettings& settings) {
    return CaseScheduler(spec, bases, settings).run();
}

}  // namespace graspsim::study
