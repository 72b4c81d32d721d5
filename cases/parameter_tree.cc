#include "cases/parameter_tree.h"

#include "cases/input_file_path.h"

#include <sstream>
#include <stdexcept>

namespace tightfit {

std::vector<std::string> ParameterTree::get_list(const std::string& name) {
  std::vector<std::string> words;
  std::istringstream text(get(name));
  for (std::string word; std::getline(text, word, ',');) {
    const auto begin = word.find_first_not_of(" \t");
    if (begin == std::string::npos) continue;
    const auto end = word.find_last_not_of(" \t");
    words.push_back(word.substr(begin, end - begin + 1));
  }
  return words;
}

Vec3 ParameterTree::get_vector(const std::string& name) {
  const std::vector<std::string> parts = get_list(name);
  if (parts.size() != 3)
    throw std::invalid_argument(name + " = '" + get(name) + "': expected three numbers");
  Vec3 v;
  for (int i = 0; i < 3; ++i) v[i] = std::stod(parts[i]);
  return v;
}

std::string ParameterTree::get_file_name(const std::string& name) {
  try {
    return resolve_input_file(get(name), case_directory);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(name + " = " + e.what());
  }
}

}  // namespace tightfit
