#include "graspsim/study/study_grid_table.h"

#include "graspsim/capacity/capacity_files.h"
#include "graspsim/error.h"
#include "graspsim/io/atomic_file.h"
#include "graspsim/study/study_case.h"
#include "graspsim/study/study_folder.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <algorithm>
#include <map>

namespace graspsim::study {

namespace {

std::string formatNumber(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

// A case error without the case's temporary scenario path ("<path>/scenario.yaml: ").
std::string shortenError(const std::string& error) {
    const std::string marker = "scenario.yaml: ";
    const std::size_t at = error.find(marker);
    std::string text = at == std::string::npos ? error : error.substr(at + marker.size());
    for (char& c : text) {
        if (c == '|') c = '/';  // a Markdown cell ends at '|'
    }
    return text;
}

// What one case adds to its cell.
std::string describeCase(const CaseRecord& record, const nlohmann::json& summary, bool approx) {
    if (record.status != CaseStatus::Ok) return (approx ? "approx: " : "") + shortenError(record.error);
    if (approx) return summary.value("engaged", false) ? "approx engaged" : "approx NOT engaged";
    std::string text = summary.value("held", false) ? "held" : "DROPPED";
    text += formatNumber(", drift %.1f mm", summary.value("object_displacement_m", 0.0) * 1000);
    text += formatNumber(", %.1f mm inside at t = 0", summary.value("initial_penetration_m", 0.0) * 1000);
    const double plan = summary.value("plan_time_s", 0.0);
    if (plan > 0) text += formatNumber("; plan %.2f s", plan);
    return text;
}

// A capacity case's cell: its measurement's figures in the command's words, and why an incomplete
// case stopped.
std::string describeCapacityCase(const CaseRecord& record, const nlohmann::json& m, bool approx) {
    const std::string prefix = approx ? "approx: " : "";
    if (record.status == CaseStatus::Failed) return prefix + shortenError(record.error);
    std::string text = prefix + capacity::describeMeasuredFigures(m);
    if (record.status == CaseStatus::Incomplete) text += " (" + shortenError(record.error) + ")";
    return text;
}

std::string findStem(const std::string& path) { return std::filesystem::path(path).stem().string(); }

}  // namespace

std::string formatGridTable(const StudySpec& spec, const std::string& folder) {
    int baseAxis = -1, modeAxis = -1;
    for (std::size_t k = 0; k < spec.axes.size(); ++k) {
        if (spec.axes[k].isBase) baseAxis = static_cast<int>(k);
        if (spec.axes[k].name == "mode") modeAxis = static_cast<int>(k);
    }
    if (baseAxis < 0) return "";
    std::vector<std::string> rows;                                // in case order
    std::map<std::pair<std::string, std::string>, std::string> cells;  // (row, base) -> text
    for (const StudyCase& c : expandCases(spec)) {
        std::string row;
        for (std::size_t k = 0; k < c.values.size(); ++k) {
            if (static_cast<int>(k) == baseAxis || static_cast<int>(k) == modeAxis) continue;
            row += (row.empty() ? "" : "; ") + c.values[k];
        }
        if (std::find(rows.begin(), rows.end(), row) == rows.end()) rows.push_back(row);
        const bool approx = modeAxis >= 0 && c.values[modeAxis] == "approx";
        std::string text = "not run";
        bool failed = false;
        if (isCaseFinished(folder, c.index)) {
            const CaseRecord record = readCaseRecord(folder, c.index);
            failed = record.status == CaseStatus::Failed;
            const nlohmann::json summary = readCaseSummary(folder, c.index, spec.command);
            text = spec.command == StudyCommand::Capacity ? describeCapacityCase(record, summary, approx)
                                                          : describeCase(record, summary, approx);
        }
        std::string& cell = cells[{row, c.values[baseAxis]}];
        const std::string withoutMode = text.substr(text.find(": ") == std::string::npos ? 0 : text.find(": ") + 2);
        if (failed && cell.find(withoutMode) != std::string::npos) continue;  // the same refusal in both modes
        if (approx) cell += (cell.empty() ? "" : "; ") + text;
        else cell = text + (cell.empty() ? "" : "; " + cell);
    }
    std::string header;
    for (std::size_t k = 0; k < spec.axes.size(); ++k) {
        if (static_cast<int>(k) != baseAxis && static_cast<int>(k) != modeAxis) header += (header.empty() ? "" : "; ") + spec.axes[k].name;
    }
    std::string table = "| " + header + " |";
    std::string rule = "|---|";
    for (const std::string& base : spec.axes[baseAxis].values) {
        table += " " + findStem(base) + " |";
        rule += "---|";
    }
    table += "\n" + rule + "\n";
    for (const std::string& row : rows) {
        table += "| " + row + " |";
        for (const std::string& base : spec.axes[baseAxis].values) table += " " + cells[{row, base}] + " |";
        table += "\n";
    }
    return table;
}

}  // namespace graspsim::study
