#include "graspsim/study/study_table.h"

#include "graspsim/error.h"
#include "graspsim/io/atomic_file.h"
#include "graspsim/study/study_case.h"
#include "graspsim/study/study_folder.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <sstream>

namespace graspsim::study {

namespace {

// A CSV field, quoted when it holds a comma, a quote or a line break.
std::string quoteCsv(const std::string& text) {
    if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

std::string formatMeasure(const nlohmann::json& summary, const std::string& key) {
    const auto it = summary.find(key);
    if (it == summary.end() || it->is_null()) return "";
    if (it->is_string()) return it->get<std::string>();
    return it->dump();
}

std::string formatHeader(const StudySpec& spec) {
    std::string header = "case";
    for (const StudyAxis& axis : spec.axes) header += "," + quoteCsv(axis.name);
    header += ",status";
    for (const std::string& measure : spec.measures) header += "," + measure;
    return header + ",error\n";
}

// One row; `record` is null for a missing case.
std::string formatRow(const StudySpec& spec, const StudyCase& studyCase, const CaseRecord* record, const nlohmann::json& summary) {
    std::string row = std::to_string(studyCase.index);
    for (const std::string& value : studyCase.values) row += "," + quoteCsv(value);
    row += "," + (record ? toString(record->status) : std::string("missing"));
    for (const std::string& measure : spec.measures) row += "," + quoteCsv(formatMeasure(summary, measure));
    return row + "," + quoteCsv(record ? record->error : "") + "\n";
}

}  // namespace

StudyTable collectStudyTable(const StudySpec& spec, const std::string& folder) {
    StudyTable table;
    table.csv = formatHeader(spec);
    for (const StudyCase& studyCase : expandCases(spec)) {
        ++table.total;
        if (!isCaseFinished(folder, studyCase.index)) {
            table.missing.push_back(studyCase.index);
            table.csv += formatRow(spec, studyCase, nullptr, nlohmann::json::object());
            continue;
        }
        const CaseRecord record = readCaseRecord(folder, studyCase.index);
        if (record.status == CaseStatus::Incomplete) table.incomplete.push_back(studyCase.index);
        if (record.status == CaseStatus::Failed) table.failed.push_back(studyCase.index);
        table.csv += formatRow(spec, studyCase, &record, readCaseSummary(folder, studyCase.index, spec.command));
    }
    return table;
}

void writeStudyTable(const std::string& folder, const StudyTable& table) {
    io::writeFileAtomically(folder + "/results.csv", table.csv);
}

std::string formatFailureCounts(std::size_t incomplete, std::size_t failed) {
    const std::string counted = std::to_string(failed) + " failed";
    return incomplete == 0 ? counted : std::to_string(incomplete) + " incomplete, " + counted;
}

std::string formatCaseList(const std::vector<int>& cases, std::size_t limit) {
    std::ostringstream text;
    for (std::size_t i = 0; i < cases.size() && i < limit; ++i) text << (i ? ", " : "") << cases[i];
    if (cases.size() > limit) text << ", ... (" << cases.size() << " in all)";
    return text.str();
}

}  // namespace graspsim::study
