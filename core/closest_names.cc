#include "core/closest_names.h"

#include <algorithm>
#include <cctype>

namespace tightfit {

namespace {

std::string lower(const std::string& text) {
  std::string folded = text;
  for (char& c : folded) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return folded;
}

}  // namespace

std::size_t edit_distance(const std::string& a_text, const std::string& b_text) {
  // Wagner-Fischer with the adjacent transposition of Damerau: three rows suffice.
  const std::string a = lower(a_text), b = lower(b_text);
  const std::size_t n = b.size();
  std::vector<std::size_t> before(n + 1), previous(n + 1), current(n + 1);
  for (std::size_t j = 0; j <= n; ++j) previous[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (std::size_t j = 1; j <= n; ++j) {
      const std::size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        current[j] = std::min(current[j], before[j - 2] + 1);
    }
    before.swap(previous);
    previous.swap(current);
  }
  return previous[n];
}

std::vector<std::string> closest_names(const std::string& unknown,
                                       const std::vector<std::string>& known, std::size_t limit) {
  const std::string needle = lower(unknown);
  std::vector<std::pair<std::size_t, std::string>> near;
  for (const std::string& name : known) {
    if (name.empty() || name == unknown) continue;
    const std::size_t distance = edit_distance(unknown, name);
    // A third of the longer name, and never all of it (a one-letter name is no nearer to
    // another one-letter name than to anything else).
    const std::size_t longer = std::max(unknown.size(), name.size());
    const std::size_t allowed = std::min(std::max<std::size_t>(1, longer / 3), longer - 1);
    const std::string hay = lower(name);
    const bool contained = needle.size() >= 3 && (hay.find(needle) != std::string::npos ||
                                                  needle.find(hay) != std::string::npos);
    if (distance <= allowed || contained) near.emplace_back(distance, name);
  }
  std::stable_sort(near.begin(), near.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<std::string> names;
  for (const auto& [distance, name] : near) {
    if (names.size() == limit) break;
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  }
  return names;
}

std::string did_you_mean(const std::string& unknown, const std::vector<std::string>& known,
                         std::size_t list_up_to) {
  auto quoted_list = [](const std::vector<std::string>& names, const char* last_separator) {
    std::string text;
    for (std::size_t k = 0; k < names.size(); ++k)
      text += (k == 0                  ? ""
               : k + 1 == names.size() ? last_separator
                                       : ", ") +
              ("'" + names[k] + "'");
    return text;
  };
  const std::vector<std::string> near = closest_names(unknown, known);
  if (!near.empty()) return "; did you mean " + quoted_list(near, " or ") + "?";
  if (!known.empty() && known.size() <= list_up_to) return "; known: " + quoted_list(known, ", ");
  return "";
}

}  // namespace tightfit
