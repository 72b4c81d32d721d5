// Registries of scenario parts by name, in the style of ASPECT's plugins: each part (a garment,
// a body, a placement, a measurement) is one file in cases/parts/ with a registration in
// scenario_parts.cc. The case file picks one by name (`set Kind = ...`) and each part reads
// its own subsection, named after it.
#pragma once

#include "cases/parameter_tree.h"

#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace tightfit {

// `Made` is what the part's parser returns: the parsed settings ready to build the part.
template <class Made>
struct PartEntry {
  std::string name;         // as the case file spells it, e.g. "cylinder"
  std::string subsection;   // the part's own subsection, e.g. "Cylinder"
  std::string description;  // one sentence for the Kind entry's documentation
  // Declares the part's entries (inside its subsection).
  std::function<void(ParameterTree&)> declare_parameters;
  // Reads them (inside its subsection) and checks them; throws std::invalid_argument naming
  // the entry at fault.
  std::function<Made(ParameterTree&)> parse;
};

template <class Made>
class PartRegistry {
 public:
  // `section` is where the parts are chosen, e.g. "Body", for documentation and messages.
  explicit PartRegistry(std::string section) : section_(std::move(section)) {}

  void add(PartEntry<Made> entry) { entries_.push_back(std::move(entry)); }
  const std::string& section() const { return section_; }
  const std::vector<PartEntry<Made>>& entries() const { return entries_; }

  // Throws std::invalid_argument naming the section and the known names.
  const PartEntry<Made>& find(const std::string& name) const {
    for (const auto& e : entries_)
      if (e.name == name) return e;
    throw std::invalid_argument(section_ + ": unknown kind '" + name + "' (known: " +
                                names_joined(", ") + ")");
  }
  std::string names_joined(const char* separator) const {
    std::string joined;
    for (const auto& e : entries_) joined += (joined.empty() ? "" : separator) + e.name;
    return joined;
  }
  // "cylinder: ...; plane: ...", for the Kind entry's documentation.
  std::string descriptions() const {
    std::string text;
    for (const auto& e : entries_)
      text += (text.empty() ? "" : " ") + e.name + ": " + e.description;
    return text;
  }

  // Declares every part's subsection inside the current one.
  void declare_parts(ParameterTree& tree) const {
    for (const auto& e : entries_) {
      if (!e.declare_parameters) continue;
      Subsection in(tree, e.subsection);
      e.declare_parameters(tree);
    }
  }
  // Parses part `name` from its subsection inside the current one; messages name the section.
  Made parse_part(ParameterTree& tree, const std::string& name) const {
    const PartEntry<Made>& e = find(name);
    Subsection in(tree, e.subsection);
    try {
      return e.parse(tree);
    } catch (const std::invalid_argument& error) {
      throw std::invalid_argument(section_ + "/" + e.subsection + ": " + error.what());
    }
  }

 private:
  std::string section_;
  std::vector<PartEntry<Made>> entries_;
};

}  // namespace tightfit
