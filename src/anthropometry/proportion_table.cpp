#include <graspsim/anthropometry/proportion_table.h>

#include <graspsim/error.h>

#include "csv_table.h"
#include "embedded_tables.h"
#include "name_list.h"

namespace graspsim::anthropometry {

namespace {

ProportionTable loadEmbedded(const std::string& file) {
    return ProportionTable::parseCsv(std::string(findEmbeddedTable(file)), findEmbeddedTableSource(file));
}

}  // namespace

ProportionTable ProportionTable::loadHand() { return loadEmbedded("hand_proportions.csv"); }

ProportionTable ProportionTable::loadBody() { return loadEmbedded("body_proportions.csv"); }

ProportionTable ProportionTable::parseCsv(const std::string& csvText,
                                          const std::string& source) {
    const CsvTable table = CsvTable::parse(csvText, source);
    table.requireColumns({"name", "value", "unit", "source"});
    ProportionTable proportions(source);
    for (std::size_t row = 0; row < table.getRowCount(); ++row) {
        const std::string& name = table.getText(row, "name");
        const std::string& unit = table.getText(row, "unit");
        // Only dimensionless ratios are stored, so no unit conversion can be forgotten here.
        if (unit != "ratio") {
            throw InputError(table.findLocation(row) + ": field 'unit' value '" + unit +
                             "' is not accepted; use ratio");
        }
        const double value = table.getNumber(row, "value");
        if (value <= 0.0) {
            throw InputError(table.findLocation(row) + ": field 'value' value '" +
                             table.getText(row, "value") +
                             "' is not accepted; use a positive ratio");
        }
        for (const auto& earlier : proportions.m_values) {
            if (earlier.first == name) {
                throw InputError(table.findLocation(row) + ": name '" + name +
                                 "' appears twice");
            }
        }
        proportions.m_values.emplace_back(name, value);
    }
    return proportions;
}

double ProportionTable::get(const std::string& name) const {
    for (const auto& [known, value] : m_values) {
        if (known == name) return value;
    }
    throw InputError(m_source + ": proportion '" + name + "' is not known; known names: " +
                     joinNames(getNames()));
}

std::vector<std::string> ProportionTable::getNames() const {
    std::vector<std::string> names;
    for (const auto& entry : m_values) names.push_back(entry.first);
    return names;
}

}  // namespace graspsim::anthropometry
