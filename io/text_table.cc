#include "io/text_table.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <utility>

namespace tightfit {

namespace {

bool is_number(const std::string& text) {
  if (text.empty() || text == "-") return true;  // a missing value does not make a column text
  char* end = nullptr;
  std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size();
}

std::string padded(const std::string& text, std::size_t width, bool right_aligned) {
  const std::string fill(width - std::min(width, text.size()), ' ');
  return right_aligned ? fill + text : text + fill;
}

}  // namespace

TextTable::TextTable(std::string title, std::vector<std::string> headers)
    : title_(std::move(title)), headers_(std::move(headers)) {}

void TextTable::add_row(std::vector<std::string> cells) {
  if (cells.size() != headers_.size())
    throw std::invalid_argument("table '" + title_ + "': a row has " +
                                std::to_string(cells.size()) + " cells for " +
                                std::to_string(headers_.size()) + " columns");
  rows_.push_back(std::move(cells));
}

std::string TextTable::render() const {
  const std::size_t n = headers_.size();
  std::vector<std::size_t> width(n);
  std::vector<bool> right_aligned(n, true);
  for (std::size_t c = 0; c < n; ++c) {
    width[c] = headers_[c].size();
    for (const auto& row : rows_) {
      width[c] = std::max(width[c], row[c].size());
      if (!is_number(row[c])) right_aligned[c] = false;
    }
  }
  const std::string gap = "  ";
  auto line = [&](const std::vector<std::string>& cells) {
    std::string text;
    for (std::size_t c = 0; c < n; ++c)
      text += (c ? gap : "") + padded(cells[c], width[c], right_aligned[c]);
    // Trailing blanks of a left-aligned last column are noise in logs.
    text.erase(text.find_last_not_of(' ') + 1);
    return text + "\n";
  };
  std::string rule;
  for (std::size_t c = 0; c < n; ++c) rule += (c ? gap : "") + std::string(width[c], '-');

  std::string out = title_.empty() ? "" : title_ + "\n";
  out += line(headers_);
  out += rule + "\n";
  for (const auto& row : rows_) out += line(row);
  return out;
}

std::ostream& operator<<(std::ostream& out, const TextTable& table) {
  return out << table.render();
}

std::string format_number(double value, int significant_digits) {
  if (std::isnan(value)) return "-";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*g", significant_digits, value);
  return buffer;
}

std::string format_fixed(double value, int decimals) {
  if (std::isnan(value)) return "-";
  char buffer[512];  // %f of a huge double is long
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

}  // namespace tightfit
