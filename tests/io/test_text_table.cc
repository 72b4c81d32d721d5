// The on-screen table: title, header, rule, numbers right-aligned and text left-aligned.
#include "io/text_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

namespace tightfit {
namespace {

TEST(TextTable, ColumnsAreAlignedUnderTheirHeaders) {
  TextTable table("Cylinder study", {"garment", "alpha", "p_mean_Pa"});
  table.add_row({"T", "1.2", "512.3"});
  table.add_row({"4 5T", "1.8", "-"});
  const std::string want =
      "Cylinder study\n"
      "garment  alpha  p_mean_Pa\n"
      "-------  -----  ---------\n"
      "T          1.2      512.3\n"
      "4 5T       1.8          -\n";
  EXPECT_EQ(table.render(), want);
  std::ostringstream out;
  out << table;
  EXPECT_EQ(out.str(), want);
}

TEST(TextTable, WideCellsWidenTheirColumn) {
  TextTable table("", {"n", "x"});
  table.add_row({"12345", "0.5"});
  EXPECT_EQ(table.render(), "    n    x\n-----  ---\n12345  0.5\n");
}

TEST(TextTable, RowOfTheWrongLengthIsRejected) {
  TextTable table("t", {"a", "b"});
  EXPECT_THROW(table.add_row({"1"}), std::invalid_argument);
}

TEST(TextTable, NumbersAreFormattedAsAsked) {
  EXPECT_EQ(format_number(1234.5678, 4), "1235");
  EXPECT_EQ(format_number(0.000123456, 3), "0.000123");
  EXPECT_EQ(format_number(std::nan(""), 4), "-");
  EXPECT_EQ(format_fixed(2.0 / 3.0, 3), "0.667");
  EXPECT_EQ(format_fixed(-1.5, 0), "-2");
  EXPECT_EQ(format_fixed(std::nan(""), 2), "-");
}

}  // namespace
}  // namespace tightfit
