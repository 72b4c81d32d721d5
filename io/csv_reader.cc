#include "io/csv_reader.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

namespace tightfit {

std::vector<std::string> csv_fields(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      fields.back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      fields.emplace_back();
    } else if (c != '\r') {
      fields.back() += c;
    }
  }
  return fields;
}

std::optional<CsvRows> CsvRows::read(const std::string& path) {
  std::ifstream in(path);
  if (!in) return std::nullopt;
  CsvRows table;
  table.path_ = path;
  std::string line;
  if (!std::getline(in, line)) return table;
  table.columns_ = csv_fields(line);
  while (std::getline(in, line)) {
    if (line.empty() || line == "\r") continue;
    std::vector<std::string> fields = csv_fields(line);
    if (fields.size() < table.columns_.size()) continue;
    table.rows_.push_back(std::move(fields));
  }
  return table;
}

std::size_t CsvRows::column(const std::string& name) const {
  for (std::size_t c = 0; c < columns_.size(); ++c)
    if (columns_[c] == name) return c;
  throw std::runtime_error(path_ + ": no column '" + name + "' in its header");
}

const std::string& CsvRows::text(std::size_t row, std::size_t column) const {
  return rows_.at(row).at(column);
}

double CsvRows::number(std::size_t row, std::size_t column) const {
  const std::string& field = text(row, column);
  if (field.empty()) return std::nan("");
  errno = 0;
  char* end = nullptr;
  const double value = std::strtod(field.c_str(), &end);
  if (end == field.c_str() || *end != '\0')
    throw std::runtime_error(path_ + ", row " + std::to_string(row + 1) + ", column '" +
                             columns_.at(column) + "': '" + field + "' is not a number");
  return value;
}

}  // namespace tightfit
