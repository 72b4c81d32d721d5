#include "cases/parameter_names.h"

#include "core/closest_names.h"
#include "core/plain_text.h"

#include <fstream>
#include <istream>

namespace tightfit {

namespace {

std::string joined(const std::vector<std::string>& path) {
  std::string text;
  for (const std::string& part : path) text += (text.empty() ? "" : "/") + part;
  return text;
}

std::string where(const std::vector<std::string>& path) {
  return path.empty() ? "the top level" : "'" + joined(path) + "'";
}

// One statement of a parameter file as deal.II reads it: comments after '#' dropped, lines
// ending in '\' joined to the next, blanks trimmed; `line` is where the statement starts.
struct Statement {
  int line = 0;
  std::string keyword, name;  // subsection NAME, end, set NAME = VALUE, include FILE
};

bool starts_with_keyword(const std::string& text, const char* keyword, std::string* rest) {
  const std::string k = keyword;
  if (text.size() < k.size()) return false;
  std::string head = text.substr(0, k.size());
  for (char& c : head) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (head != k) return false;
  if (text.size() > k.size() && text[k.size()] != ' ' && text[k.size()] != '\t') return false;
  *rest = trimmed(text.substr(k.size()));
  return true;
}

std::vector<Statement> statements(std::istream& in) {
  std::vector<Statement> list;
  std::string pending;
  int start = 0, number = 0;
  for (std::string raw; std::getline(in, raw);) {
    ++number;
    if (pending.empty()) start = number;
    const auto hash = raw.find('#');
    std::string text = trimmed(hash == std::string::npos ? raw : raw.substr(0, hash));
    if (!text.empty() && text.back() == '\\') {
      pending += text.substr(0, text.size() - 1) + " ";
      continue;
    }
    text = trimmed(pending + text);
    pending.clear();
    if (text.empty()) continue;
    Statement s;
    s.line = start;
    std::string rest;
    if (starts_with_keyword(text, "subsection", &rest)) {
      s.keyword = "subsection";
      s.name = rest;
    } else if (starts_with_keyword(text, "set", &rest)) {
      s.keyword = "set";
      s.name = trimmed(rest.substr(0, rest.find('=')));
    } else if (starts_with_keyword(text, "end", &rest) && rest.empty()) {
      s.keyword = "end";
    } else {
      s.keyword = "other";  // include, or a line deal.II itself refuses
    }
    list.push_back(s);
  }
  return list;
}

}  // namespace

DeclaredParameters::DeclaredParameters(std::istream& short_prm) {
  std::vector<std::string> path;
  levels_[""];
  for (const Statement& s : statements(short_prm)) {
    if (s.keyword == "subsection") {
      levels_[joined(path)].subsections.push_back(s.name);
      path.push_back(s.name);
      levels_[joined(path)];
    } else if (s.keyword == "end" && !path.empty()) {
      path.pop_back();
    } else if (s.keyword == "set") {
      levels_[joined(path)].entries.push_back(s.name);
    }
  }
}

const DeclaredParameters::Level* DeclaredParameters::level(
    const std::vector<std::string>& path) const {
  const auto found = levels_.find(joined(path));
  return found == levels_.end() ? nullptr : &found->second;
}

std::string DeclaredParameters::check_entry(const std::vector<std::string>& path,
                                            const std::string& name) const {
  const Level* here = level(path);
  if (!here) return "";  // the subsection itself is reported
  for (const std::string& e : here->entries)
    if (e == name) return "";
  std::string message = where(path) + " has no entry '" + name + "'";
  // A subsection written as an entry, or an entry of another subsection nearby.
  std::vector<std::string> known = here->entries;
  known.insert(known.end(), here->subsections.begin(), here->subsections.end());
  if (!closest_names(name, known).empty()) return message + did_you_mean(name, known);
  // An entry written in the wrong subsection ("Final alpha" at the top level): where it is.
  std::vector<std::string> elsewhere;
  for (const auto& [at, other] : levels_)
    for (const std::string& e : other.entries)
      if (edit_distance(e, name) == 0) elsewhere.push_back(at.empty() ? e : at + "/" + e);
  if (!elsewhere.empty()) {
    std::string list;
    for (const std::string& e : elsewhere) list += (list.empty() ? "'" : "' or '") + e;
    return message + "; it is an entry of another subsection: did you mean " + list + "'?";
  }
  return message + did_you_mean(name, known);
}

std::string DeclaredParameters::check_subsection(const std::vector<std::string>& path,
                                                 const std::string& name) const {
  const Level* here = level(path);
  if (!here) return "";
  for (const std::string& s : here->subsections)
    if (s == name) return "";
  return where(path) + " has no subsection '" + name + "'" + did_you_mean(name, here->subsections);
}

std::string DeclaredParameters::first_unknown_name_in(const std::string& case_file) const {
  std::ifstream in(case_file);
  std::vector<std::string> path;
  for (const Statement& s : statements(in)) {
    std::string problem;
    if (s.keyword == "subsection") {
      problem = check_subsection(path, s.name);
      path.push_back(s.name);
    } else if (s.keyword == "end") {
      if (path.empty()) return "";  // unbalanced: deal.II's own message says so
      path.pop_back();
    } else if (s.keyword == "set") {
      problem = check_entry(path, s.name);
    }
    if (!problem.empty()) return "line " + std::to_string(s.line) + ": " + problem;
  }
  return "";
}

std::string selection_refusal(const std::string& value, const std::string& pattern_description) {
  std::string options_text;
  bool multiple = false;
  for (const char* kind : {"[Selection ", "[MultipleSelection "}) {
    const auto begin = pattern_description.find(kind);
    if (begin == std::string::npos) continue;
    const auto first = begin + std::string(kind).size();
    const auto end = pattern_description.find(']', first);
    options_text = pattern_description.substr(first, end == std::string::npos ? end : end - first);
    multiple = std::string(kind) == "[MultipleSelection ";
    break;
  }
  if (options_text.empty()) return "";
  std::vector<std::string> options;
  for (std::size_t start = 0; start <= options_text.size();) {
    const auto bar = std::min(options_text.find('|', start), options_text.size());
    options.push_back(trimmed(options_text.substr(start, bar - start)));
    start = bar + 1;
  }
  std::vector<std::string> words{trimmed(value)};
  if (multiple) {
    words.clear();
    for (std::size_t start = 0; start <= value.size();) {
      const auto comma = std::min(value.find(',', start), value.size());
      words.push_back(trimmed(value.substr(start, comma - start)));
      start = comma + 1;
    }
  }
  for (const std::string& word : words) {
    if (multiple && word.empty()) continue;
    bool known = false;
    for (const std::string& option : options) known = known || option == word;
    if (known) continue;
    std::string listed;
    for (const std::string& option : options)
      listed += (listed.empty() ? "'" : ", '") + option + "'";
    return "'" + word + "' is not one of " + listed + did_you_mean(word, options, 0);
  }
  return "";
}

}  // namespace tightfit
