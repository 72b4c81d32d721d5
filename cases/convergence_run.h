// Mesh-convergence study of a case (the paper's Section 7.4, Figure 14; docs/validation.md): the
// case run at edge lengths divided by a constant ratio (2 by default) level by level on each
// backend, with the observed order, the Richardson-extrapolated pressure and Roache's GCI of
// every load step; for a case with named regions (Measurements/List: regions) the same for each
// region's mean and peak pressure (cases/region_convergence.h).
//
// Files written into the output directory (every row flushed as soon as it is known, so a
// study that stops keeps what it finished):
//
// convergence.csv, one row per backend, level and load step (long format):
//   backend      backend name (as in the registry)
//   level        0 for the case's own mesh, k for Mesh scale s0 / r^k (r the ratio, 2 by default)
//   mesh_scale   Garment/Mesh scale used at this level (dimensionless)
//   n_vertices   welded vertices of the garment mesh
//   edge_m       mean rest edge length of the mesh, m
//   step         load step (0 is the settling step)
//   alpha        the body's morph parameter (a cylinder: r / R0)
//   p_mean_Pa    mean contact pressure over the vertices in contact, Pa
//   p_theory_Pa  closed form of the case's law and end condition, Pa
//   rel_error    (p_mean - p_theory) / p_theory; empty where p_theory is 0
//
// convergence_summary.csv, one row per backend and load step, from the levels it finished:
//   backend, step, alpha  as above
//   n_levels             levels that finished this step
//   edge_fine_m          mean edge length of the finest of them, m
//   ratio                refinement ratio used: the measured mean-edge ratio of the finest
//                        three (or two) levels, geometric mean (nominally the study's ratio)
//   p_fine_Pa            mean pressure on the finest level, Pa
//   p_theory_Pa          closed form, Pa
//   observed_order       p = ln((f3 - f2) / (f2 - f1)) / ln r from the finest three levels
//                        (f1 finest); with two levels the element's formal order, 2, assumed
//   order_observed       1 when observed, 0 when assumed
//   p_richardson_Pa      Richardson-extrapolated pressure f1 + (f1 - f2) / (r^p - 1), Pa
//   gci_fine             Roache's GCI of the finest level, a fraction of p_fine (0.01 = 1%)
//   safety_factor        1.25 with three or more levels, 3 with two (Roache 1994)
//   rel_error_fine       (p_fine - p_theory) / p_theory
//   rel_error_richardson (p_richardson - p_theory) / p_theory
//   error_order          ln(|e2| / |e1|) / ln r, the order of the error against the closed form
//                        from the finest two levels
// Undefined values (no pressure yet, oscillating sequences) are empty fields.
//
// With regions, convergence_regions.csv, one row per backend, level, load step and region:
//   backend, level, mesh_scale, n_vertices, edge_m, step, alpha   as in convergence.csv
//   region              the region's name (Measurements/Regions/Definitions)
//   p_mean_Pa           mean pressure over the region's contact area, Pa (cases/region_pressure.h)
//   p_peak_Pa           largest vertex pressure in the region, Pa
//   contact_area_m2     the region's contact area, m^2
//   n_contact_vertices  contact vertices with a share in the region
// and convergence_regions_summary.csv, one row per backend, load step and region, from the
// levels that finished the step:
//   backend, step, alpha, region, n_levels, edge_fine_m, ratio   as above
//   p_mean_fine_Pa, mean_order, mean_order_observed, p_mean_richardson_Pa, mean_gci_fine
//                       the finest level's mean pressure and its estimates, as in
//                       convergence_summary.csv
//   p_peak_fine_Pa, peak_order, peak_order_observed, p_peak_richardson_Pa, peak_gci_fine
//                       the same for the peak pressure
//   safety_factor       1.25 with three or more levels, 3 with two
//
// Each run's own pressure.csv and pressure_theta.csv go to <dir>/<backend>/level_<k>/ (no VTU).
//
// Every level's scenario is made once, before any level runs (so that a bad level is found
// before the coarse ones have run for minutes), and each backend in turn runs that same
// scenario: a run starts with Scenario::prepare_step(0), which puts the body back in its
// starting shape (ScenarioBody::morph), and no run changes anything else in a scenario. A case
// whose placement dresses the garment (docs/dressing.md) thus dresses it once per level.
#pragma once

#include "cases/case_parameters.h"
#include "cases/convergence_analysis.h"
#include "cases/region_convergence.h"
#include "cases/region_pressure.h"
#include "cases/scenario_run.h"

#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace tightfit {

struct NamedBackendFactory {
  std::string name;
  BackendFactory create;
};

struct ConvergenceLevel {
  int level = 0;
  double mesh_scale = 1.0;
  int n_vertices = 0;
  double edge_m = 0.0;  // mean rest edge length, m
  // Wall time of the level: its run and the making of its scenario (made once for all the
  // backends, counted in each backend's level).
  double seconds = 0.0;
  double cpu_seconds = 0.0;  // the same, the process's CPU time (every thread's)
  RunResult run;
  // The pressure in the study's regions at each step that finished, [step][region].
  std::vector<std::vector<RegionPressure>> region_pressures;
};

struct BackendConvergence {
  std::string backend;
  std::vector<ConvergenceLevel> levels;  // the levels that were started, coarse to fine
  bool completed = false;
  std::string failure;  // why the study of this backend stopped, if it did
};

struct ConvergenceSummaryRow {
  std::string backend;
  int step = 0;
  double alpha = 0.0;
  double edge_fine_m = 0.0;
  double ratio = 2.0;
  double p_fine_Pa = 0.0;
  double p_theory_Pa = 0.0;
  ConvergenceEstimate estimate;
  double rel_error_fine = 0.0;
  double rel_error_richardson = 0.0;
};

struct RegionConvergenceRow {
  std::string backend;
  int step = 0;
  double alpha = 0.0;
  RegionConvergence estimate;
};

struct ConvergenceStudy {
  std::vector<BackendConvergence> backends;
  std::vector<ConvergenceSummaryRow> summary;
  std::vector<std::string> regions;  // the regions studied (none without a regions measurement)
  std::vector<RegionConvergenceRow> region_summary;
  int scenarios_made = 0;  // make_scenario calls of the study: one per level
  bool completed() const;
};

struct ConvergenceSettings {
  int n_levels = 3;
  double ratio = 2.0;  // the edge lengths are divided by it from one level to the next
  // The regions to study, by name; empty: every region of the case's regions measurement.
  std::vector<std::string> regions;
  // Called once every level's scenario is made and before any runs, with level 0's (the case's
  // own mesh, VTU output off): what the command prints the case's header from.
  std::function<void(const Scenario& level_0)> on_levels_made;
};

// The case at level `level` of a study: Garment/Mesh scale and the edge lengths divided by
// ratio^level, VTU output off.
CaseParameters convergence_level_parameters(const CaseParameters& base, int level, double ratio);

// Runs `parameters` at settings.n_levels meshes (Mesh scale s0, s0/r, s0/r^2, ... with s0 the
// case's own and r settings.ratio) on each backend in turn, VTU output off, and writes the
// files above into `output_dir`. A backend that fails at one level stops its own study (the
// next backend still runs). Throws std::invalid_argument when n_levels < 2, the ratio is not
// above 1, a region named is not one of the case's, or a level's setup is invalid.
ConvergenceStudy run_convergence_study(const CaseParameters& parameters,
                                       const ConvergenceSettings& settings,
                                       const std::vector<NamedBackendFactory>& backends,
                                       const std::string& output_dir, std::ostream& log);

// The summary rows of one backend's study, one per load step that finished on two or more
// levels.
std::vector<ConvergenceSummaryRow> summarise_convergence(const BackendConvergence& study);

// The region rows of one backend's study, one per load step and region, for the steps that
// finished on two or more levels; `regions` names the columns of each level's region_pressures.
std::vector<RegionConvergenceRow> summarise_region_convergence(
    const BackendConvergence& study, const std::vector<std::string>& regions);

}  // namespace tightfit
