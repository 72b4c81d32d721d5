// Cross-backend comparison: one case, one mesh, two backends, step by step.
#pragma once

#include "cases/scenario_run.h"

#include <iosfwd>
#include <string>

namespace tightfit {

struct ComparisonResult {
  RunResult first, second;
  bool completed() const { return first.completed && second.completed; }
};

// Runs the case on `first_name` into DIR/<first_name> and on `second_name` into
// DIR/<second_name> (each with its own pressure.csv and VTU series), then writes
// DIR/compare.csv (one row per step both finished: step, alpha, p_mean_Pa_<first>,
// p_mean_Pa_<second>, p_theory_Pa, rel_diff = (second - first) / first, ...) and, with VTU
// output on, DIR/difference_NNNN.vtu + difference.pvd: the second backend's garment with the
// per-vertex pressure difference (same mesh, so vertex by vertex). Each step is compared as
// soon as the second backend finishes it; until then the first backend's pressure and contact
// flag of every vertex are kept (9 bytes a vertex a step, on every rank when VTU output is on).
ComparisonResult run_comparison(Scenario& setup, const std::string& first_name,
                                const BackendFactory& make_first, const std::string& second_name,
                                const BackendFactory& make_second, const std::string& output_dir,
                                std::ostream& log);

}  // namespace tightfit
