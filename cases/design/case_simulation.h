// One simulation of a design (docs/design.md): the design's case run with its garment cut to
// given relaxed circumferences at the measuring points (cases/design/stocking_cut.h), and the
// mean and peak pressure over each point's band (cases/design/band_pressure.h).
#pragma once

#include "cases/design/design_loop.h"
#include "cases/design/design_target.h"
#include "core/tapered_tube_garment.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace tightfit {

struct CaseSimulationSetup {
  std::string case_file;
  std::vector<std::string> case_overrides;
  std::string garment_kind = "tapered tube";  // or limb tube (cut to the body's leg)
  PiecewiseLinear limb_girths_m;
  std::vector<NamedValue> points;  // name, height along the garment (m)
  double band_width_m = 0.02;
};

// A simulation that did not finish (the solver failed, or the run was interrupted).
class DesignRunFailed : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Runs the case on `backend` (empty: the case's own) with the garment cut to
// `circumferences_m`, writing the run's files into `output_dir` and its progress into
// output_dir/run.log. With `start_from` (a garment VTU of an earlier cut of the same mesh) the
// garment starts where that run left it (Placement/Kind = from file) instead of the case's
// placement: the next iteration's garment is already on the limb (a cut whose mesh differs
// starts from the case's placement). Throws DesignRunFailed when the run stops early,
// std::invalid_argument for a case the cut makes invalid.
std::vector<BandPressure> simulate_cut(const CaseSimulationSetup& setup,
                                       const std::vector<double>& circumferences_m,
                                       const std::string& backend, const std::string& output_dir,
                                       const std::string& start_from = "");

}  // namespace tightfit
