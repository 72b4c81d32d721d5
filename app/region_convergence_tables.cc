#include "app/region_convergence_tables.h"

#include <cmath>
#include <map>
#include <string>

namespace tightfit {

namespace {

// 100 (value - reference) / reference, or NaN.
double percent_from(double value, double reference) {
  return 100.0 * (value - reference) / reference;
}

std::string order_text(const ConvergenceEstimate& e) {
  return format_fixed(e.order, 2) + (e.order_observed ? "" : " (assumed)");
}

}  // namespace

std::vector<TextTable> region_convergence_tables(const ConvergenceStudy& study) {
  if (study.region_summary.empty()) return {};
  // Each backend's last step with an estimate, and its rows by region.
  std::map<std::string, int> last_step;
  for (const RegionConvergenceRow& row : study.region_summary) last_step[row.backend] = row.step;
  std::map<std::pair<std::string, std::string>, const RegionConvergenceRow*> estimate;
  for (const RegionConvergenceRow& row : study.region_summary)
    if (row.step == last_step[row.backend]) estimate[{row.backend, row.estimate.region}] = &row;

  TextTable levels(
      "Pressure by region at each level (each backend's last load step); beside each, its "
      "difference from the Richardson estimate",
      {"backend", "step", "level", "vertices", "edge [mm]", "time [s]", "region", "p_mean [Pa]",
       "from Richardson [%]", "p_peak [Pa]", "from Richardson [%]"});
  for (const BackendConvergence& backend : study.backends) {
    const auto step = last_step.find(backend.backend);
    if (step == last_step.end()) continue;
    for (const ConvergenceLevel& l : backend.levels) {
      // The level's row of that step, if it finished it.
      std::size_t at = l.run.steps.size();
      for (std::size_t k = 0; k < l.run.steps.size(); ++k)
        if (l.run.steps[k].step == step->second) at = k;
      if (at >= l.region_pressures.size()) continue;
      for (std::size_t r = 0; r < study.regions.size(); ++r) {
        const RegionPressure& p = l.region_pressures[at][r];
        const RegionConvergence& e = estimate.at({backend.backend, study.regions[r]})->estimate;
        levels.add_row({backend.backend, std::to_string(step->second), std::to_string(l.level),
                        std::to_string(l.n_vertices), format_fixed(1e3 * l.edge_m, 2),
                        format_fixed(l.seconds, 1), study.regions[r], format_fixed(p.mean_Pa, 1),
                        format_fixed(percent_from(p.mean_Pa, e.mean.extrapolated), 2),
                        format_fixed(p.peak_Pa, 1),
                        format_fixed(percent_from(p.peak_Pa, e.peak.extrapolated), 2)});
      }
    }
  }

  TextTable summary(
      "Mesh convergence by region (each backend's last load step; order from the finest three "
      "levels, Richardson estimate, GCI of the finest, Roache 1994)",
      {"backend", "step", "region", "levels", "p_mean fine [Pa]", "order", "Richardson [Pa]",
       "GCI [%]", "p_peak fine [Pa]", "order", "Richardson [Pa]", "GCI [%]"});
  for (const RegionConvergenceRow& row : study.region_summary) {
    if (row.step != last_step[row.backend]) continue;
    const RegionConvergence& r = row.estimate;
    summary.add_row({row.backend, std::to_string(row.step), r.region, std::to_string(r.n_levels),
                     format_fixed(r.mean_fine_Pa, 1), order_text(r.mean),
                     format_fixed(r.mean.extrapolated, 1), format_fixed(100.0 * r.mean.gci_fine, 2),
                     format_fixed(r.peak_fine_Pa, 1), order_text(r.peak),
                     format_fixed(r.peak.extrapolated, 1),
                     format_fixed(100.0 * r.peak.gci_fine, 2)});
  }
  return {levels, summary};
}

}  // namespace tightfit
