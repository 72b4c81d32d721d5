// The per-cell block (fem/cell_table.h): each cell's view returns what was appended for it, in
// order, and a cell of the wrong length is refused rather than shifting every later cell.
#include "fem/cell_table.h"

#include <gtest/gtest.h>

#include <array>
#include <stdexcept>
#include <vector>

namespace tightfit {
namespace {

TEST(CellTable, ViewsReturnEachCellsValues) {
  CellTable<double> table;
  table.reset(3);
  EXPECT_EQ(table.size(), 0);
  table.push_back(std::vector<double>{1.0, 2.0, 3.0});
  table.push_back(std::array<double, 3>{4.0, 5.0, 6.0});
  table.shrink_to_fit();
  ASSERT_EQ(table.size(), 2);
  EXPECT_EQ(table.per_cell(), 3u);
  for (int cell = 0; cell < 2; ++cell) {
    ASSERT_EQ(table[cell].size(), 3u);
    for (unsigned int i = 0; i < 3; ++i) EXPECT_EQ(table[cell][i], 3.0 * cell + i + 1.0);
  }
  table.reset(2);
  EXPECT_EQ(table.size(), 0);
}

TEST(CellTable, RefusesACellOfTheWrongLength) {
  CellTable<int> table;
  table.reset(2);
  EXPECT_THROW(table.push_back(std::vector<int>{1, 2, 3}), std::logic_error);
  EXPECT_EQ(table.size(), 0);
}

}  // namespace
}  // namespace tightfit
