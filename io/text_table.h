// A table for the terminal: a title, a header, a rule, and aligned columns (the summary
// `tightfit run` prints). Columns whose cells are all numbers are right-aligned so digits line
// up; other columns are left-aligned.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace tightfit {

class TextTable {
 public:
  TextTable(std::string title, std::vector<std::string> headers);

  // Throws std::invalid_argument when the number of cells is not the number of columns.
  void add_row(std::vector<std::string> cells);

  // Every line ends with '\n'.
  std::string render() const;

  std::size_t n_rows() const { return rows_.size(); }

 private:
  std::string title_;
  std::vector<std::string> headers_;
  std::vector<std::vector<std::string>> rows_;
};

std::ostream& operator<<(std::ostream& out, const TextTable& table);

// `value` with `significant_digits` significant digits (%g); NaN as "-".
std::string format_number(double value, int significant_digits = 4);
// `value` with `decimals` digits after the point (%f); NaN as "-".
std::string format_fixed(double value, int decimals);

}  // namespace tightfit
