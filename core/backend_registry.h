// Backends register themselves by name (as ASPECT's plugins do); the parameter file picks one.
#pragma once

#include "core/backend.h"
#include "core/dressing_stage.h"
#include "core/load_step.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace dealii {
class ParameterHandler;
}

namespace tightfit {

struct BackendEntry {
  std::string name;
  std::string description;
  // Whether the backend applies Coulomb friction (Problem::friction_coefficient); one that does
  // not refuses a problem with friction rather than solving a frictionless one in its place.
  bool applies_friction = false;
  // The backend's own subsection of a case file (for example "Mass spring").
  std::string subsection;
  // Declares that subsection in the handler.
  std::function<void(dealii::ParameterHandler&)> declare_parameters;
  // Reads that subsection and creates the backend for `problem` with the shared stop rule (the
  // case file's Solver entries, core/load_step.h).
  std::function<std::unique_ptr<Backend>(const Problem&, const StopRule&,
                                         dealii::ParameterHandler&)>
      create;
  // The backend's dressing stage (core/dressing_stage.h), or null when it has none.
  std::shared_ptr<const DressingStage> dressing_stage;
};

class BackendRegistry {
 public:
  void add(BackendEntry entry);
  // Throws std::invalid_argument listing the known names when `name` is unknown.
  const BackendEntry& find(const std::string& name) const;
  const std::vector<BackendEntry>& entries() const { return entries_; }
  // The dressing stage of the first backend that has one: a garment is dressed on it whichever
  // backend then solves the load steps (docs/dressing.md). Throws std::logic_error when none
  // has one.
  const DressingStage& dressing_stage() const;
  // "massspring|fem", for a Patterns::Selection.
  std::string names_joined(const char* separator) const;

 private:
  std::vector<BackendEntry> entries_;
};

// Every backend built into this program (defined where the backends are linked together).
const BackendRegistry& backend_registry();

}  // namespace tightfit
