#include <graspsim/anthropometry/subject.h>

#include <graspsim/anthropometry/units.h>
#include <graspsim/error.h>

#include "csv_table.h"
#include "embedded_tables.h"

#include <cmath>
#include <sstream>

namespace graspsim::anthropometry {

namespace {

std::string formatValue(double value) {
    if (std::isnan(value)) return "nan";  // the sign of a NaN means nothing to a reader
    std::ostringstream text;
    text << value;
    return text.str();
}

void checkRange(double value, const std::string& where, const std::string& quantity,
                double lower, double upper, const std::string& unit) {
    if (std::isfinite(value) && value >= lower && value <= upper) return;
    std::ostringstream message;
    message << where << " value " << formatValue(value) << " is not accepted; " << quantity
            << " must be a finite number in [" << lower << ", " << upper << "] " << unit;
    throw InputError(message.str());
}

}  // namespace

void validateBodyMass(double mass, const std::string& source) {
    checkRange(mass, source + ":", "body mass", kMinBodyMass, kMaxBodyMass, "kg");
}

void validateStature(double stature, const std::string& source) {
    checkRange(stature, source + ":", "stature", kMinStature, kMaxStature, "m");
}

void validateSubject(const Subject& subject, const std::string& source) {
    checkRange(subject.mass, source + ": field 'mass'", "body mass", kMinBodyMass,
               kMaxBodyMass, "kg");
    checkRange(subject.stature, source + ": field 'stature'", "stature", kMinStature,
               kMaxStature, "m");
}

Subject getReferenceSubject(Sex sex) {
    const std::string file = "de_leva_1996_reference_subjects.csv";
    const CsvTable table =
        CsvTable::parse(findEmbeddedTable(file), findEmbeddedTableSource(file));
    table.requireColumns({"sex", "body_mass_kg", "stature_mm"});
    for (std::size_t row = 0; row < table.getRowCount(); ++row) {
        if (parseSex(table.getText(row, "sex"), table.findLocation(row)) != sex) continue;
        Subject subject;
        subject.sex = sex;
        subject.mass = table.getNumber(row, "body_mass_kg");
        subject.stature = fromMillimetres(table.getNumber(row, "stature_mm"));
        validateSubject(subject, table.findLocation(row));
        return subject;
    }
    throw InputError(table.getSource() + ": no row for sex '" + toString(sex) + "'");
}

}  // namespace graspsim::anthropometry
