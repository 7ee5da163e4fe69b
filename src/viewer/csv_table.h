#pragma once
// The CSV files graspsim writes (results/result_files.h), read back: comma-separated, one header
// line, fields in double quotes where they hold commas (events.csv's reason).

#include <string>
#include <vector>

namespace graspsim::viewer {

struct CsvTable {
    std::string path;  // for messages
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;  // each as long as the header

    // Throws InputError unless the header starts with `columns`.
    void requireColumns(const std::vector<std::string>& columns) const;
    // Field (row, column) as a number ("inf" accepted); throws InputError naming the line and column.
    double getNumber(std::size_t row, std::size_t column) const;
};

// Throws InputError naming the line of a row whose field count differs from the header's.
CsvTable readCsvTable(const std::string& path, const std::string& text);

}  // namespace graspsim::viewer
