#include <graspsim/anthropometry/joint_ranges.h>

#include <graspsim/anthropometry/units.h>
#include <graspsim/error.h>

#include "csv_table.h"
#include "embedded_tables.h"
#include "name_list.h"

#include <cmath>

namespace graspsim::anthropometry {

namespace {

const char* const kJointRangesFile = "joint_ranges.csv";

double readAngle(const CsvTable& table, std::size_t row, const std::string& column) {
    const double degrees = table.getNumber(row, column);
    if (std::abs(degrees) > 360.0) {
        throw InputError(table.findLocation(row) + ": field '" + column + "' value '" +
                         table.getText(row, column) +
                         "' is not accepted; use degrees in [-360, 360]");
    }
    return degrees;
}

}  // namespace

JointRanges JointRanges::loadDefault() {
    return parseCsv(std::string(findEmbeddedTable(kJointRangesFile)),
                    findEmbeddedTableSource(kJointRangesFile));
}

JointRanges JointRanges::parseCsv(const std::string& csvText, const std::string& source) {
    const CsvTable table = CsvTable::parse(csvText, source);
    table.requireColumns({"joint", "lower_deg", "upper_deg", "source"});
    JointRanges ranges(source);
    for (std::size_t row = 0; row < table.getRowCount(); ++row) {
        const std::string& joint = table.getText(row, "joint");
        const double lower = readAngle(table, row, "lower_deg");
        const double upper = readAngle(table, row, "upper_deg");
        if (!(lower < upper)) {
            throw InputError(table.findLocation(row) + ": joint '" + joint + "' lower_deg '" +
                             table.getText(row, "lower_deg") +
                             "' is not accepted; it must be less than upper_deg '" +
                             table.getText(row, "upper_deg") + "'");
        }
        for (const auto& earlier : ranges.m_ranges) {
            if (earlier.first == joint) {
                throw InputError(table.findLocation(row) + ": joint '" + joint +
                                 "' appears twice");
            }
        }
        ranges.m_ranges.emplace_back(joint, JointRange{fromDegrees(lower), fromDegrees(upper)});
    }
    return ranges;
}

const JointRange& JointRanges::get(const std::string& joint) const {
    for (const auto& entry : m_ranges) {
        if (entry.first == joint) return entry.second;
    }
    throw InputError(m_source + ": joint '" + joint + "' is not known; known joints: " +
                     joinNames(getJointNames()));
}

std::vector<std::string> JointRanges::getJointNames() const {
    std::vector<std::string> names;
    for (const auto& entry : m_ranges) names.push_back(entry.first);
    return names;
}

}  // namespace graspsim::anthropometry
