#include "core/plain_text.h"

#include <cstdio>

namespace tightfit {

std::string trimmed(const std::string& text) {
  const char* blanks = " \t\r\n";
  const auto first = text.find_first_not_of(blanks);
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(blanks) - first + 1);
}

std::string point_text(const Vec2& x) {
  char text[80];
  std::snprintf(text, sizeof text, "(%.6g, %.6g)", x.x(), x.y());
  return text;
}

}  // namespace tightfit
