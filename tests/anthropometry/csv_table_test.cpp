#include "csv_table.h"

#include <graspsim/error.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace graspsim::anthropometry {
namespace {

using ::testing::HasSubstr;
using ::testing::StrEq;
using ::testing::ThrowsMessage;

const char* const kText =
    "# a comment line\n"
    "# another, with a comma\n"
    "name , mass_pct\r\n"
    "\n"
    "head, 6.94\r\n"
    "# a comment between rows\n"
    "trunk,abc\n";

TEST(CsvTable, SkipsCommentsAndBlankLinesAndTrimsFields) {
    const CsvTable table = CsvTable::parse(kText, "t.csv");
    ASSERT_EQ(table.getRowCount(), 2u);
    EXPECT_EQ(table.getText(0, "name"), "head");
    EXPECT_DOUBLE_EQ(table.getNumber(0, "mass_pct"), 6.94);
    EXPECT_EQ(table.getLineNumber(0), 5);
    EXPECT_EQ(table.getLineNumber(1), 7);
    EXPECT_EQ(table.findLocation(1), "t.csv:7");
}

TEST(CsvTable, NonNumericFieldNamesFileLineFieldAndValue) {
    const CsvTable table = CsvTable::parse(kText, "t.csv");
    EXPECT_THAT([&] { table.getNumber(1, "mass_pct"); },
                ThrowsMessage<InputError>(
                    StrEq("t.csv:7: field 'mass_pct' value 'abc' is not a number")));
}

TEST(CsvTable, RejectsTrailingCharactersEmptyFieldsAndNonFiniteNumbers) {
    const CsvTable table = CsvTable::parse("a,b,c,d\n1.5x,,nan,inf\n", "t.csv");
    for (const char* column : {"a", "b", "c", "d"}) {
        EXPECT_THROW(table.getNumber(0, column), InputError) << column;
    }
}

TEST(CsvTable, RowWithWrongFieldCountIsRejected) {
    EXPECT_THAT([] { CsvTable::parse("a,b\n1,2\n3\n", "t.csv"); },
                ThrowsMessage<InputError>(
                    StrEq("t.csv:3: row has 1 fields; the header has 2")));
}

TEST(CsvTable, MissingColumnListsTheHeader) {
    const CsvTable table = CsvTable::parse("a,b\n1,2\n", "t.csv");
    EXPECT_THAT([&] { table.requireColumns({"a", "c"}); },
                ThrowsMessage<InputError>(
                    StrEq("t.csv: column 'c' is missing; the header has a, b")));
}

TEST(CsvTable, TextWithoutHeaderIsRejected) {
    EXPECT_THAT([] { CsvTable::parse("# only a comment\n\n", "t.csv"); },
                ThrowsMessage<InputError>(HasSubstr("t.csv: no header row")));
}

}  // namespace
}  // namespace graspsim::anthropometry
