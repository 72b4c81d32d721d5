// A measurement of a scenario (docs/scenarios.md): what a run records at every load step
// beside the generic pressure summary. Each kind is one file in cases/parts/ and a
// registration in scenario_parts.cc; the case file lists the ones it wants in
// Measurements/List.
#pragma once

#include "io/text_table.h"

#include <optional>
#include <string>
#include <vector>

namespace tightfit {

struct Scenario;
struct StepMeasurement;

// Where a run's files go and who writes them (every MPI rank runs; the first writes tables).
struct RunFiles {
  std::string directory;
  bool write_tables = false;
  std::string path(const std::string& file_name) const;
};

class Measurement {
 public:
  virtual ~Measurement() = default;
  // The pressure the scenario's closed form predicts at this step, Pa, if this measurement
  // knows one: it fills pressure.csv's p_theory_Pa and rel_error. The first measurement
  // listed that knows one gives it.
  virtual std::optional<double> reference_pressure_Pa(const Scenario& /*scenario*/,
                                                      const StepMeasurement& /*step*/) const {
    return std::nullopt;
  }
  // Columns this measurement adds to pressure.csv (and to the summary table), and their values
  // at one step in the same order.
  virtual std::vector<std::string> columns() const { return {}; }
  virtual std::vector<double> values(const Scenario& /*scenario*/,
                                     const StepMeasurement& /*step*/) const {
    return {};
  }
  // Called once before the first load step is solved, the body in its starting shape: what
  // needs the body (the landmarks a named region is built from) is found here, so that a body
  // on which it cannot be found stops the run before any solve.
  virtual void prepare(const Scenario& /*scenario*/) {}
  // Called after every load step is measured (on every rank, the step whole), and once when
  // the run ends (with every step that finished), to write files of its own into
  // `files.directory`. At the end only the last step holds its per-vertex arrays (state, field),
  // and only on the first rank, the one that writes (files.write_tables): what a measurement
  // needs of the others' it takes in after_step.
  virtual void after_step(const Scenario& /*scenario*/, const StepMeasurement& /*step*/,
                          const RunFiles& /*files*/) {}
  virtual void after_run(const Scenario& /*scenario*/,
                         const std::vector<StepMeasurement>& /*steps*/, const RunFiles& /*files*/) {
  }
  // Tables shown on screen when the run ends, after the pressure summary (every step that
  // finished is in `steps`, possibly none). Called on every rank, when the steps' per-vertex
  // arrays are released: a table of per-vertex values is made from what after_step kept.
  virtual std::vector<TextTable> summary_tables(
      const Scenario& /*scenario*/, const std::vector<StepMeasurement>& /*steps*/) const {
    return {};
  }
  // The files it wrote, for the run's closing line.
  virtual std::vector<std::string> file_names() const { return {}; }
};

}  // namespace tightfit
