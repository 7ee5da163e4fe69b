#include "csv_table.h"

#include "graspsim/error.h"

#include <cstdlib>
#include <sstream>

namespace graspsim::viewer {

namespace {

std::vector<std::string> splitCsvLine(const std::string& line) {
    std::vector<std::string> fields(1);
    bool quoted = false;
    for (char c : line) {
        if (c == '"') quoted = !quoted;
        else if (c == ',' && !quoted) fields.emplace_back();
        else if (c != '\r') fields.back() += c;
    }
    return fields;
}

std::string joinColumns(const std::vector<std::string>& columns) {
    std::string text;
    for (const std::string& c : columns) text += (text.empty() ? "" : ",") + c;
    return text;
}

}  // namespace

CsvTable readCsvTable(const std::string& path, const std::string& text) {
    CsvTable table;
    table.path = path;
    std::istringstream lines(text);
    std::string line;
    if (!std::getline(lines, line)) throw InputError(path + ": is empty; expected a header line");
    table.header = splitCsvLine(line);
    for (int number = 2; std::getline(lines, line); ++number) {
        if (line.empty()) continue;
        std::vector<std::string> fields = splitCsvLine(line);
        if (fields.size() != table.header.size()) {
            throw InputError(path + ":" + std::to_string(number) + ": " + std::to_string(fields.size()) + " fields, the header has " +
                             std::to_string(table.header.size()));
        }
        table.rows.push_back(std::move(fields));
    }
    return table;
}

void CsvTable::requireColumns(const std::vector<std::string>& columns) const {
    bool ok = header.size() >= columns.size();
    for (std::size_t c = 0; ok && c < columns.size(); ++c) ok = header[c] == columns[c];
    if (!ok) throw InputError(path + ": columns are not graspsim's; expected " + joinColumns(columns));
}

double CsvTable::getNumber(std::size_t row, std::size_t column) const {
    const std::string& text = rows[row][column];
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0') {
        throw InputError(path + ":" + std::to_string(row + 2) + ": field '" + header[column] + "' value '" + text +
                         "' is not a number");
    }
    return value;
}

}  // namespace graspsim::viewer
