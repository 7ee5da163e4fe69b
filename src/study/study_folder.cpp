#include "graspsim/study/study_folder.h"

#include "graspsim/error.h"
#include "graspsim/io/atomic_file.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>

namespace graspsim::study {

namespace fs = std::filesystem;

namespace {

constexpr const char* kStudyFile = "study.json";

std::string formatIndex(int index) {
    char text[16];
    std::snprintf(text, sizeof text, "%04d", index);
    return text;
}

// A JSON object: graspsim writes nothing else into a study folder, and value() throws a type
// error (an internal error, exit 1) on an array or a number.
nlohmann::json readJson(const std::string& path) {
    nlohmann::json json;
    try {
        json = nlohmann::json::parse(io::readTextFile(path));
    } catch (const nlohmann::json::exception& e) {
        throw InputError(path + ": is not readable JSON (" + std::string(e.what()) + ")");
    }
    if (!json.is_object()) throw InputError(path + ": value '" + json.dump().substr(0, 80) + "' is not accepted; graspsim writes a JSON object here");
    return json;
}

// A text field of a JSON object that readJson read; `fallback` when absent.
std::string findText(const nlohmann::json& json, const char* key, const std::string& fallback, const std::string& path) {
    const auto found = json.find(key);
    if (found == json.end()) return fallback;
    if (!found->is_string()) throw InputError(path + ": field '" + key + "' value '" + found->dump() + "' is not accepted; it is text");
    return found->get<std::string>();
}

// Anything in the folder that a study run did not write.
bool holdsOtherFiles(const std::string& folder) {
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(folder, ec)) {
        (void)entry;
        return true;
    }
    return false;
}

std::string replaceAll(std::string text, const std::string& from, const std::string& to) {
    if (from.empty()) return text;
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
        text.replace(at, from.size(), to);
    }
    return text;
}

// The case's process was told to write into its temporary folder and says so ("files in
// out/cases/0007.tmp-123"); the committed copy of what it printed names the folder it is kept in.
void renameInPrintedFile(const std::string& path, const std::string& tmpFolder, const std::string& target) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) return;  // a case refused before its process started
    const std::string text = io::readTextFile(path);
    if (text.find(tmpFolder) == std::string::npos) return;
    io::writeFileAtomically(path, replaceAll(text, tmpFolder, target));
}

}  // namespace

std::string toString(CaseStatus status) {
    switch (status) {
        case CaseStatus::Ok: return "ok";
        case CaseStatus::Incomplete: return "incomplete";
        case CaseStatus::Failed: return "failed";
    }
    return "failed";
}

std::string calcStudyFingerprint(const StudySpec& spec, const std::string& baseText) {
    std::uint64_t hash = 14695981039346656037ull;  // FNV-1a 64
    const std::string text = spec.text + '\0' + baseText;
    for (unsigned char c : text) hash = (hash ^ c) * 1099511628211ull;
    char hex[20];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
    return hex;
}

void prepareStudyFolder(const std::string& folder, const StudySpec& spec, const std::string& baseText) {
    const std::string fingerprint = calcStudyFingerprint(spec, baseText);
    const std::string studyPath = folder + "/" + kStudyFile;
    std::error_code ec;
    if (fs::exists(studyPath, ec)) {
        const nlohmann::json known = readJson(studyPath);
        if (findText(known, "fingerprint", "", studyPath) == fingerprint) return;
        throw InputError("--out: folder '" + folder + "' holds the results of another study ('" + findText(known, "name", "?", studyPath) +
                         "' from " + findText(known, "source", "?", studyPath) + ", or this study before its file or base scenario changed); "
                         "give a new folder, or remove that one to start again");
    }
    if (fs::exists(folder, ec) && (!fs::is_directory(folder, ec) || holdsOtherFiles(folder))) {
        throw InputError("--out: folder '" + folder + "' is not empty and is not a study's folder; give a new or empty folder");
    }
    fs::create_directories(folder + "/cases", ec);
    if (ec) throw InputError("--out: folder '" + folder + "' cannot be created (" + ec.message() + ")");
    nlohmann::ordered_json study;
    study["name"] = spec.name;
    study["source"] = fs::absolute(spec.source).lexically_normal().string();
    study["fingerprint"] = fingerprint;
    io::writeFileAtomically(folder + "/study.yaml", spec.text);
    io::writeFileAtomically(studyPath, study.dump(2) + "\n");
}

StudySpec loadFolderStudy(const std::string& folder) {
    const std::string studyPath = folder + "/" + kStudyFile;
    std::error_code ec;
    if (!fs::is_regular_file(studyPath, ec)) {
        throw InputError(folder + ": is not a study's output folder (no " + kStudyFile + "); give the --out folder of `graspsim study run` or `submit`");
    }
    const nlohmann::json known = readJson(studyPath);
    return parseStudy(io::readTextFile(folder + "/study.yaml"), findText(known, "source", folder + "/study.yaml", studyPath));
}

std::string findCaseFolder(const std::string& folder, int index) { return folder + "/cases/" + formatIndex(index); }

bool isCaseFinished(const std::string& folder, int index) {
    std::error_code ec;
    return fs::is_regular_file(findCaseFolder(folder, index) + "/case.json", ec);
}

void removeCaseTemporaries(const std::string& folder, int index) {
    const std::string prefix = formatIndex(index) + ".tmp-";
    std::error_code ec;
    std::vector<fs::path> stale;
    for (const auto& entry : fs::directory_iterator(folder + "/cases", ec)) {
        if (entry.path().filename().string().rfind(prefix, 0) == 0) stale.push_back(entry.path());
    }
    for (const fs::path& path : stale) fs::remove_all(path, ec);
}

void commitCase(const std::string& folder, const std::string& tmpFolder, const CaseRecord& record) {
    const std::string target = findCaseFolder(folder, record.index);
    renameInPrintedFile(tmpFolder + "/stdout.txt", tmpFolder, target);
    renameInPrintedFile(tmpFolder + "/stderr.txt", tmpFolder, target);
    nlohmann::ordered_json json;
    json["case"] = record.index;
    json["status"] = toString(record.status);
    json["error"] = replaceAll(record.error, tmpFolder, target);
    json["values"] = record.values;
    io::writeFileAtomically(tmpFolder + "/case.json", json.dump(2) + "\n");
    std::error_code ec;
    fs::remove_all(target, ec);  // a folder without case.json: a run that died between the two renames
    fs::rename(tmpFolder, target, ec);
    if (ec) throw InputError("cannot move case folder '" + tmpFolder + "' to '" + target + "' (" + ec.message() + ")");
}

CaseRecord readCaseRecord(const std::string& folder, int index) {
    const std::string path = findCaseFolder(folder, index) + "/case.json";
    const nlohmann::json json = readJson(path);
    CaseRecord record;
    try {
        record.index = json.value("case", index);
        const std::string status = json.value("status", "failed");
        record.status = status == "ok" ? CaseStatus::Ok : status == "incomplete" ? CaseStatus::Incomplete : CaseStatus::Failed;
        record.error = json.value("error", "");
        record.values = json.value("values", std::vector<std::string>{});
    } catch (const nlohmann::json::type_error& e) {
        throw InputError(path + ": is not a graspsim case record (" + std::string(e.what()) + ")");
    }
    return record;
}

nlohmann::json readCaseSummary(const std::string& folder, int index, StudyCommand command) {
    const std::string path = findCaseFolder(folder, index) + "/" + nameResultFile(command);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return nlohmann::json::object();
    const nlohmann::json json = readJson(path);
    if (command == StudyCommand::Simulate) return json;
    const auto measurements = json.find("measurements");
    if (measurements == json.end() || !measurements->is_array() || measurements->size() != 1 || !measurements->front().is_object()) {
        throw InputError(path + ": is not the capacity.json of one measurement (\"measurements\": [{...}])");
    }
    return measurements->front();
}

}  // namespace graspsim::study
