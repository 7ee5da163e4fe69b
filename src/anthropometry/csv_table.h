#pragma once
// A small reader for the anthropometry CSV files (private to the anthropometry layer).
// Format: optional '#' comment lines and blank lines anywhere, then a header row, then data
// rows; fields are separated by commas, with no quoting, and surrounding spaces are trimmed.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace graspsim::anthropometry {

class CsvTable {
public:
    /// Parses `text`; `source` names the file in error messages. Throws InputError when there
    /// is no header or a row has a different number of fields than the header.
    static CsvTable parse(std::string_view text, const std::string& source);

    const std::string& getSource() const { return m_source; }
    std::size_t getRowCount() const { return m_rows.size(); }
    /// The 1-based line of `row` in the file, for error messages.
    int getLineNumber(std::size_t row) const { return m_rows.at(row).line; }
    /// "<source>:<line>" of `row`, the prefix of every message about that row.
    std::string findLocation(std::size_t row) const;

    /// Throws InputError naming the file and the columns it has if `column` is missing.
    void requireColumns(const std::vector<std::string>& columns) const;
    const std::string& getText(std::size_t row, const std::string& column) const;
    /// The field as a finite number; throws InputError naming file, line, field and value.
    double getNumber(std::size_t row, const std::string& column) const;

private:
    struct Row {
        int line = 0;
        std::vector<std::string> fields;
    };
    std::size_t findColumn(const std::string& column) const;

    std::string m_source;
    std::vector<std::string> m_header;
    std::vector<Row> m_rows;
};

}  // namespace graspsim::anthropometry
