#include "io/csv_table.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace tightfit {

std::string CsvCell::format(double value) {
  if (std::isnan(value)) return "";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.10g", value);
  return buffer;
}

std::string CsvCell::format(long long value) {
  return std::to_string(value);
}

std::string CsvCell::quoted(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';  // a quote inside a quoted field is doubled
    out += c;
  }
  return out + "\"";
}

CsvTable::CsvTable(const std::string& path, const std::vector<std::string>& columns)
    : path_(path), n_columns_(columns.size()) {
  if (columns.empty())
    throw std::invalid_argument("CSV table '" + path + "' needs at least one column");
  out_.open(path, std::ios::out | std::ios::trunc);
  if (!out_) throw std::runtime_error("cannot open CSV file '" + path + "' for writing");
  write_line(std::vector<CsvCell>(columns.begin(), columns.end()));
}

void CsvTable::write_row(const std::vector<CsvCell>& cells) {
  if (cells.size() != n_columns_)
    throw std::invalid_argument("CSV table '" + path_ + "': a row has " +
                                std::to_string(cells.size()) + " cells for " +
                                std::to_string(n_columns_) + " columns");
  write_line(cells);
  ++n_rows_;
}

void CsvTable::write_line(const std::vector<CsvCell>& cells) {
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (i > 0) out_ << ',';
    out_ << cells[i].text();
  }
  out_ << '\n';
  out_.flush();
  if (!out_) throw std::runtime_error("cannot write to CSV file '" + path_ + "'");
}

}  // namespace tightfit
