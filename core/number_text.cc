#include "core/number_text.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

namespace tightfit {

std::optional<double> whole_number(const std::string& text) {
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    return std::nullopt;  // no number at the start, or out of range
  }
  if (used == 0 || used != text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<double> auto_or_number(const std::string& text, const std::string& entry) {
  if (text == "auto") return std::nullopt;
  const std::optional<double> value = whole_number(text);
  if (!value) throw std::invalid_argument(entry + " = '" + text + "': neither auto nor a number");
  return value;
}

std::optional<int> auto_or_count(const std::string& text, const std::string& entry, int largest) {
  if (text == "auto") return std::nullopt;
  const bool digits_only =
      !text.empty() && text.size() <= 9 && std::all_of(text.begin(), text.end(), [](char c) {
        return std::isdigit(static_cast<unsigned char>(c)) != 0;
      });
  const long value = digits_only ? std::stol(text) : -1;
  if (value < 0 || value > largest)
    throw std::invalid_argument(entry + " = '" + text + "': neither auto nor a count from 0 to " +
                                std::to_string(largest));
  return int(value);
}

}  // namespace tightfit
