// The final design's report (docs/design.md, "What it writes"): at each measuring point the
// target, Laplace's pressure on the designed circumference, the simulated band mean and peak,
// and, when the cut was simulated once more on another backend (Design/Check backend), that
// backend's band mean and peak beside them with its error against the target.
#pragma once

#include "cases/design/design_loop.h"
#include "io/text_table.h"

#include <string>
#include <vector>

namespace tightfit {

// The final cut simulated once more on another backend.
struct DesignCheck {
  std::string backend;              // empty: no check asked
  std::vector<BandPressure> bands;  // one per point; empty when the run did not finish
  std::string failure;              // why it did not finish
  double tolerance_Pa = 1.0 * 133.322387415;
};

// The points whose check mean lies farther than the check's tolerance from their target, in
// the points' order (a band without contact, NaN, counts as outside); empty when the check
// holds one band per point, every one within. Throws std::invalid_argument when the check holds
// bands but not one per point.
std::vector<std::string> check_outside(const DesignProblem& problem, const DesignCheck& check);

// design.csv: point, height_m, girth_m, circumference_m, target_mmHg, laplace_mmHg, mean_mmHg,
// peak_mmHg, and for a check that finished check_mean_mmHg, check_peak_mmHg and check_error_mmHg
// (its mean minus the target). Throws std::runtime_error naming the file when it cannot be
// written.
void write_design_csv(const std::string& path, const DesignProblem& problem,
                      const DesignIteration& last, const DesignCheck& check);

// The same as a table on screen, mmHg, under `title`.
TextTable design_table(const std::string& title, const DesignProblem& problem,
                       const DesignIteration& last, const DesignCheck& check);

}  // namespace tightfit
