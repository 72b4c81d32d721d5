// CSV tables read back (a previous run's regions.csv or pressure.csv), in the format
// io/csv_table.h writes: a header line of column names, comma-separated fields, text quoted as
// RFC 4180 says (a quoted field may hold commas; a doubled quote is one quote), an empty field
// for a missing number.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace tightfit {

class CsvRows {
 public:
  // Reads `path` whole. Nothing (std::nullopt) when the file cannot be opened; a file that
  // opens but has no header line is an empty table with no columns. Rows with fewer fields than
  // the header are skipped (a row cut short by a run that stopped while writing), as are empty
  // lines.
  static std::optional<CsvRows> read(const std::string& path);

  const std::vector<std::string>& columns() const { return columns_; }
  std::size_t n_rows() const { return rows_.size(); }

  // The index of column `name`. Throws std::runtime_error naming the file and the column when
  // the header has no such column.
  std::size_t column(const std::string& name) const;

  // Field `column` of row `row`, as text.
  const std::string& text(std::size_t row, std::size_t column) const;
  // The same as a number: NaN for an empty field, "inf"/"-inf" as infinities. Throws
  // std::runtime_error naming the file, the row (1 = the first after the header) and the
  // column when the field is not a number.
  double number(std::size_t row, std::size_t column) const;

 private:
  std::string path_;
  std::vector<std::string> columns_;
  std::vector<std::vector<std::string>> rows_;
};

// One CSV line's fields (a line of a file, without its line end; a trailing '\r' is dropped).
std::vector<std::string> csv_fields(const std::string& line);

}  // namespace tightfit
