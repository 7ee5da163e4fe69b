#include "csv_table.h"

#include "name_list.h"

#include <graspsim/error.h>

#include <charconv>
#include <cmath>
#include <system_error>

namespace graspsim::anthropometry {

namespace {

std::string_view trim(std::string_view text) {
    const char* const blanks = " \t\r";
    const std::size_t first = text.find_first_not_of(blanks);
    if (first == std::string_view::npos) return {};
    const std::size_t last = text.find_last_not_of(blanks);
    return text.substr(first, last - first + 1);
}

std::vector<std::string> splitFields(std::string_view line) {
    std::vector<std::string> fields;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = line.find(',', start);
        fields.emplace_back(trim(line.substr(start, comma - start)));
        if (comma == std::string_view::npos) return fields;
        start = comma + 1;
    }
}

}  // namespace

CsvTable CsvTable::parse(std::string_view text, const std::string& source) {
    CsvTable table;
    table.m_source = source;
    int lineNumber = 0;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        const std::string_view line = trim(text.substr(start, end - start));
        start = end + 1;
        ++lineNumber;
        if (line.empty() || line.front() == '#') continue;
        std::vector<std::string> fields = splitFields(line);
        if (table.m_header.empty()) {
            table.m_header = std::move(fields);
            continue;
        }
        if (fields.size() != table.m_header.size()) {
            throw InputError(source + ":" + std::to_string(lineNumber) + ": row has " +
                             std::to_string(fields.size()) + " fields; the header has " +
                             std::to_string(table.m_header.size()));
        }
        table.m_rows.push_back(Row{lineNumber, std::move(fields)});
    }
    if (table.m_header.empty()) {
        throw InputError(source + ": no header row; a CSV table needs a header and data rows");
    }
    return table;
}

std::string CsvTable::findLocation(std::size_t row) const {
    return m_source + ":" + std::to_string(getLineNumber(row));
}

void CsvTable::requireColumns(const std::vector<std::string>& columns) const {
    for (const std::string& column : columns) findColumn(column);
}

std::size_t CsvTable::findColumn(const std::string& column) const {
    for (std::size_t i = 0; i < m_header.size(); ++i) {
        if (m_header[i] == column) return i;
    }
    throw InputError(m_source + ": column '" + column + "' is missing; the header has " +
                     joinNames(m_header));
}

const std::string& CsvTable::getText(std::size_t row, const std::string& column) const {
    return m_rows.at(row).fields[findColumn(column)];
}

double CsvTable::getNumber(std::size_t row, const std::string& column) const {
    const std::string& text = getText(row, column);
    double value = 0.0;
    const char* const end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, value);
    // from_chars accepts "nan" and "inf"; a table entry must be an ordinary number.
    if (text.empty() || error != std::errc() || stop != end || !std::isfinite(value)) {
        throw InputError(findLocation(row) + ": field '" + column + "' value '" + text +
                         "' is not a number");
    }
    return value;
}

}  // namespace graspsim::anthropometry
