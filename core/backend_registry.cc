#include "core/backend_registry.h"

#include <stdexcept>

namespace tightfit {

void BackendRegistry::add(BackendEntry entry) {
  entries_.push_back(std::move(entry));
}

const BackendEntry& BackendRegistry::find(const std::string& name) const {
  for (const auto& entry : entries_)
    if (entry.name == name) return entry;
  throw std::invalid_argument("Solver/Backend: unknown backend '" + name +
                              "'; known: " + names_joined(", "));
}

const DressingStage& BackendRegistry::dressing_stage() const {
  for (const auto& entry : entries_)
    if (entry.dressing_stage) return *entry.dressing_stage;
  throw std::logic_error("no backend built into this program has a dressing stage; known: " +
                         names_joined(", "));
}

std::string BackendRegistry::names_joined(const char* separator) const {
  std::string joined;
  for (const auto& entry : entries_) joined += (joined.empty() ? "" : separator) + entry.name;
  return joined;
}

}  // namespace tightfit
