#include <graspsim/anthropometry/segment_table.h>

#include <graspsim/anthropometry/units.h>
#include <graspsim/error.h>

#include "csv_table.h"
#include "embedded_tables.h"
#include "name_list.h"

#include <sstream>

namespace graspsim::anthropometry {

namespace {

const char* const kDeLevaFile = "de_leva_1996_table4.csv";

// Reads a number that must lie in (lower, upper], or [lower, upper] if lowerIncluded.
double readInRange(const CsvTable& table, std::size_t row, const std::string& column,
                   double lower, double upper, bool lowerIncluded) {
    const double value = table.getNumber(row, column);
    const bool aboveLower = lowerIncluded ? value >= lower : value > lower;
    if (aboveLower && value <= upper) return value;
    std::ostringstream message;
    message << table.findLocation(row) << ": field '" << column << "' value '"
            << table.getText(row, column) << "' is not accepted; use a number in "
            << (lowerIncluded ? "[" : "(") << lower << ", " << upper << "]";
    throw InputError(message.str());
}

SegmentParameters readSegment(const CsvTable& table, std::size_t row) {
    SegmentParameters segment;
    segment.name = table.getText(row, "segment");
    segment.proximalLandmark = table.getText(row, "proximal_landmark");
    segment.distalLandmark = table.getText(row, "distal_landmark");
    // No human segment reaches 10 m; the bound only rejects absurd entries.
    segment.length = fromMillimetres(readInRange(table, row, "length_mm", 0, 10000, false));
    segment.massFraction = fromPercent(readInRange(table, row, "mass_pct", 0, 100, false));
    segment.comFraction = fromPercent(readInRange(table, row, "com_pct", 0, 100, true));
    segment.gyrationSagittal =
        fromPercent(readInRange(table, row, "r_sagittal_pct", 0, 100, false));
    segment.gyrationTransverse =
        fromPercent(readInRange(table, row, "r_transverse_pct", 0, 100, false));
    segment.gyrationLongitudinal =
        fromPercent(readInRange(table, row, "r_longitudinal_pct", 0, 100, false));
    return segment;
}

}  // namespace

SegmentTable SegmentTable::loadDeLeva(Sex sex) {
    return parseCsv(std::string(findEmbeddedTable(kDeLevaFile)), sex,
                    findEmbeddedTableSource(kDeLevaFile));
}

SegmentTable SegmentTable::parseCsv(const std::string& csvText, Sex sex,
                                    const std::string& source) {
    const CsvTable table = CsvTable::parse(csvText, source);
    table.requireColumns({"sex", "segment", "proximal_landmark", "distal_landmark", "length_mm",
                          "mass_pct", "com_pct", "r_sagittal_pct", "r_transverse_pct",
                          "r_longitudinal_pct"});
    SegmentTable segments(sex, source);
    for (std::size_t row = 0; row < table.getRowCount(); ++row) {
        if (parseSex(table.getText(row, "sex"), table.findLocation(row)) != sex) continue;
        SegmentParameters segment = readSegment(table, row);
        for (const SegmentParameters& earlier : segments.m_segments) {
            if (earlier.name == segment.name) {
                throw InputError(table.findLocation(row) + ": segment '" + segment.name +
                                 "' appears twice for sex '" + toString(sex) + "'");
            }
        }
        segments.m_segments.push_back(std::move(segment));
    }
    if (segments.m_segments.empty()) {
        throw InputError(source + ": no rows for sex '" + toString(sex) + "'");
    }
    return segments;
}

const SegmentParameters& SegmentTable::getSegment(const std::string& name) const {
    std::vector<std::string> known;
    for (const SegmentParameters& segment : m_segments) {
        if (segment.name == name) return segment;
        known.push_back(segment.name);
    }
    throw InputError(m_source + ": segment '" + name + "' is not in the " + toString(m_sex) +
                     " table; known segments: " + joinNames(known));
}

double SegmentTable::calcWholeBodyMassFractionSum() const {
    double sum = getSegment("head").massFraction + getSegment("trunk").massFraction;
    for (const char* limbSegment : {"upper_arm", "forearm", "hand", "thigh", "shank", "foot"}) {
        sum += 2.0 * getSegment(limbSegment).massFraction;  // left and right
    }
    return sum;
}

double SegmentTable::calcTrunkPartsMassFractionSum() const {
    return getSegment("upper_trunk").massFraction + getSegment("middle_trunk").massFraction +
           getSegment("lower_trunk").massFraction;
}

}  // namespace graspsim::anthropometry
