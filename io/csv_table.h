// CSV tables written row by row (pressure.csv, pressure_theta.csv, sweeps).
//
// Each row goes to disk (flushed) as soon as it is written, so a run that stops keeps every
// finished row. Format:
//   - comma separated, '\n' line ends, a header line of the column names;
//   - floating-point numbers with 10 significant digits (%.10g), integers as integers;
//   - NaN as an empty field (read back as missing by pandas, numpy.genfromtxt, gnuplot and
//     spreadsheets), infinities as "inf" and "-inf";
//   - text quoted (RFC 4180) only when it holds a comma, a double quote or a line break.
#pragma once

#include <fstream>
#include <string>
#include <type_traits>
#include <vector>

namespace tightfit {

// One field of a row: a number or a piece of text.
class CsvCell {
 public:
  template <typename T, typename = std::enable_if_t<std::is_arithmetic_v<T>>>
  CsvCell(T value) : text_(format(value)) {}  // NOLINT: implicit, so rows read {1, 0.5, "T"}
  CsvCell(const char* text) : text_(quoted(text)) {}         // NOLINT
  CsvCell(const std::string& text) : text_(quoted(text)) {}  // NOLINT

  const std::string& text() const { return text_; }

 private:
  static std::string format(double value);
  static std::string format(long long value);
  template <typename T>
  static std::string format(T value) {
    if constexpr (std::is_floating_point_v<T>)
      return format(static_cast<double>(value));
    else
      return format(static_cast<long long>(value));
  }
  static std::string quoted(const std::string& text);

  std::string text_;
};

class CsvTable {
 public:
  // Creates (truncates) `path` and writes the header. Throws std::runtime_error naming the path
  // when it cannot be opened or written; std::invalid_argument when `columns` is empty.
  CsvTable(const std::string& path, const std::vector<std::string>& columns);

  // Writes and flushes one row. Throws std::invalid_argument when the number of cells is not
  // the number of columns, std::runtime_error naming the path when the write fails.
  void write_row(const std::vector<CsvCell>& cells);

  const std::string& path() const { return path_; }
  std::size_t n_columns() const { return n_columns_; }
  std::size_t n_rows() const { return n_rows_; }

 private:
  void write_line(const std::vector<CsvCell>& cells);

  std::string path_;
  std::size_t n_columns_;
  std::size_t n_rows_ = 0;
  std::ofstream out_;
};

}  // namespace tightfit
