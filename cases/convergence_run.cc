#include "cases/convergence_run.h"

#include "cases/region_reader.h"
#include "cases/scenario.h"
#include "core/closest_names.h"
#include "core/step_heartbeat.h"
#include "io/csv_table.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <limits>
#include <optional>
#include <ostream>
#include <stdexcept>

namespace tightfit {

namespace {

constexpr double not_defined = std::numeric_limits<double>::quiet_NaN();

// Linear triangles: the pressure error is expected to fall like h^2 (the assumed order when
// only two levels finished).
constexpr double formal_order = 2.0;

std::vector<std::string> convergence_columns() {
  return {"backend", "level", "mesh_scale", "n_vertices",  "edge_m",
          "step",    "alpha", "p_mean_Pa",  "p_theory_Pa", "rel_error"};
}

std::vector<std::string> summary_columns() {
  return {"backend",         "step",      "alpha",         "n_levels",       "edge_fine_m",
          "ratio",           "p_fine_Pa", "p_theory_Pa",   "observed_order", "order_observed",
          "p_richardson_Pa", "gci_fine",  "safety_factor", "rel_error_fine", "rel_error_richardson",
          "error_order"};
}

std::vector<std::string> region_columns() {
  return {"backend", "level",  "mesh_scale", "n_vertices", "edge_m",          "step",
          "alpha",   "region", "p_mean_Pa",  "p_peak_Pa",  "contact_area_m2", "n_contact_vertices"};
}

std::vector<std::string> region_summary_columns() {
  return {"backend",
          "step",
          "alpha",
          "region",
          "n_levels",
          "edge_fine_m",
          "ratio",
          "p_mean_fine_Pa",
          "mean_order",
          "mean_order_observed",
          "p_mean_richardson_Pa",
          "mean_gci_fine",
          "p_peak_fine_Pa",
          "peak_order",
          "peak_order_observed",
          "p_peak_richardson_Pa",
          "peak_gci_fine",
          "safety_factor"};
}

// The regions a study reads: the indices into the case's regions measurement of the names
// asked for (all of them when none is), checked before anything runs.
std::vector<std::size_t> chosen_regions(const CaseParameters& parameters,
                                        const std::vector<std::string>& asked,
                                        std::vector<std::string>* names) {
  const CaseRegions case_regions = make_case_regions(parameters);
  if (!case_regions.reader) {
    if (asked.empty()) return {};
    throw std::invalid_argument(
        "--regions: the case measures no regions (Measurements/List does "
        "not list regions), so there is no region '" +
        asked.front() + "'");
  }
  std::vector<std::string> known;
  for (const BodyRegion& region : case_regions.reader->regions()) known.push_back(region.name);
  std::vector<std::size_t> indices;
  if (asked.empty())
    for (std::size_t k = 0; k < known.size(); ++k) indices.push_back(k);
  for (const std::string& name : asked) {
    const auto found = std::find(known.begin(), known.end(), name);
    if (found == known.end()) {
      std::string list;
      for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
      throw std::invalid_argument("--regions: no region '" + name +
                                  "' in Measurements/Regions/Definitions (the case's regions: " +
                                  list + ")" + did_you_mean(name, known));
    }
    indices.push_back(static_cast<std::size_t>(found - known.begin()));
  }
  for (std::size_t k : indices) names->push_back(known[k]);
  return indices;
}

// A closed form to measure the error against: the scenario's, where it predicts contact.
bool has_closed_form(double p_theory_Pa) {
  return std::isfinite(p_theory_Pa) && p_theory_Pa > 0;
}

double relative(double value, double reference) {
  return has_closed_form(reference) ? (value - reference) / reference : not_defined;
}

// The process's CPU time so far, s (every thread's; on a machine shared with other work the
// measure of a level's cost, where the wall time also counts the others').
double process_cpu_seconds() {
  return double(std::clock()) / CLOCKS_PER_SEC;
}

// A level's scenario, made once for every backend's run, and the wall and CPU time making it
// took, s.
struct MadeLevel {
  std::unique_ptr<Scenario> scenario;
  int n_vertices = 0;
  double seconds = 0.0;
  double cpu_seconds = 0.0;
};

// Before a long study: the size of each level, so that a user sees what is coming.
void print_level_sizes(std::ostream& log, const std::vector<MadeLevel>& levels) {
  log << "  levels:";
  double made_seconds = 0.0;
  for (std::size_t k = 0; k < levels.size(); ++k) {
    log << (k == 0 ? " " : "; ") << k << ": " << levels[k].n_vertices << " vertices, "
        << levels[k].scenario->mesh.triangles.size() << " triangles";
    made_seconds += levels[k].seconds;
  }
  log << "\n  (made in " << duration_text(made_seconds)
      << ", once for every backend; each level's time, and an estimate of the next one's, is "
         "printed as the level ends)\n";
}

// The time the next level should take: this level's, scaled by the growth in vertices to the
// power the two levels before measured (the cost's order in the vertex count), or, with one
// level measured, 1.5 (an explicit solver: N vertices times N^(1/2) frames, the stable time step
// falling with the edge length). The measured order is kept within 1 to 3.
struct LevelTiming {
  int n_vertices = 0;
  double seconds = 0.0;
};
double expected_seconds(const std::vector<LevelTiming>& done, int next_vertices, bool* measured) {
  const LevelTiming& last = done.back();
  double order = 1.5;
  *measured = false;
  if (done.size() >= 2) {
    const LevelTiming& before = done[done.size() - 2];
    if (before.seconds > 0 && last.seconds > 0 && last.n_vertices > before.n_vertices) {
      order = std::clamp(std::log(last.seconds / before.seconds) /
                             std::log(double(last.n_vertices) / before.n_vertices),
                         1.0, 3.0);
      *measured = true;
    }
  }
  return last.seconds * std::pow(double(next_vertices) / last.n_vertices, order);
}

// Where a study's rows go (null: not written, on the other MPI ranks) and which regions it reads.
struct StudyTables {
  CsvTable* levels = nullptr;
  CsvTable* regions = nullptr;
  std::vector<std::size_t> region_indices;
};

// Runs `backend` on the levels' scenarios, coarse to fine, until one fails. The last backend
// to run a level releases its scenario (`release_levels`).
BackendConvergence run_backend_levels(std::vector<MadeLevel>& levels,
                                      const NamedBackendFactory& backend,
                                      const std::string& output_dir, const StudyTables& tables,
                                      bool release_levels, std::ostream& log) {
  const int n_levels = static_cast<int>(levels.size());
  namespace fs = std::filesystem;
  using clock = std::chrono::steady_clock;
  BackendConvergence study;
  study.backend = backend.name;
  double study_seconds = 0.0;  // the levels' times so far, their scenarios' making included
  double study_cpu_seconds = 0.0;
  std::vector<LevelTiming> timings;
  for (int level = 0; level < n_levels; ++level) {
    const clock::time_point level_start = clock::now();
    const double level_cpu_start = process_cpu_seconds();
    Scenario* const setup = levels[level].scenario.get();
    ConvergenceLevel l;
    l.level = level;
    l.mesh_scale = setup->parameters.garment.mesh_scale;
    l.n_vertices = setup->mesh.n_vertices;
    l.edge_m = setup->mean_edge_length_m;
    log << "Backend " << backend.name << ", level " << level << " (mesh scale " << l.mesh_scale
        << ", " << l.n_vertices << " vertices, mean edge " << 1e3 * l.edge_m << " mm):\n";
    const std::string dir =
        (fs::path(output_dir) / backend.name / ("level_" + std::to_string(level))).string();
    // The regions are read as the regions measurement reads them, each step as it finishes
    // (its per-vertex arrays are then held): this level's own copy of the measurement, its
    // named shapes resolved when load step 0 finishes, on the body in the starting shape that
    // run_scenario prepared the run's own on.
    CaseRegions regions;
    if (!tables.region_indices.empty()) regions = make_case_regions(setup->parameters);
    const StepObserver read_regions = [&](const StepMeasurement& m) {
      if (!regions.reader) return;
      if (l.region_pressures.empty()) regions.measurement->prepare(*setup);
      const std::vector<RegionPressure> all = regions.reader->region_pressures(*setup, m);
      std::vector<RegionPressure> chosen;
      for (std::size_t k : tables.region_indices) {
        chosen.push_back(all[k]);
        if (tables.regions)
          tables.regions->write_row({backend.name, level, l.mesh_scale, l.n_vertices, l.edge_m,
                                     m.step, m.alpha, regions.reader->regions()[k].name,
                                     all[k].mean_Pa, all[k].peak_Pa, all[k].contact_area_m2,
                                     all[k].n_contact_vertices});
      }
      l.region_pressures.push_back(std::move(chosen));
    };
    try {
      l.run = run_scenario(*setup, backend.create, dir, log, read_regions);
    } catch (const std::exception& e) {
      // A backend that cannot even start (bad subsection, failed allocation) stops its own
      // study, not the other backends'.
      l.run.backend = backend.name;
      l.run.failure = e.what();
    }
    // The study reads the steps' scalars only; each level's files are written.
    for (StepMeasurement& m : l.run.steps) release_vertex_arrays(m);
    for (const StepMeasurement& m : l.run.steps)
      if (tables.levels)
        tables.levels->write_row({backend.name, level, l.mesh_scale, l.n_vertices, l.edge_m, m.step,
                                  m.alpha, m.p_mean_Pa(), m.p_theory_Pa,
                                  relative(m.p_mean_Pa(), m.p_theory_Pa)});
    if (release_levels) levels[level].scenario.reset();
    const bool completed = l.run.completed;
    const std::string failure = l.run.failure;
    l.seconds =
        levels[level].seconds + std::chrono::duration<double>(clock::now() - level_start).count();
    l.cpu_seconds = levels[level].cpu_seconds + process_cpu_seconds() - level_cpu_start;
    timings.push_back({l.n_vertices, l.seconds});
    study_seconds += l.seconds;
    study_cpu_seconds += l.cpu_seconds;
    log << "  " << backend.name << " level " << level << " took "
        << duration_text(timings.back().seconds) << " (" << duration_text(l.cpu_seconds)
        << " of CPU; this backend so far " << duration_text(study_seconds) << ", "
        << duration_text(study_cpu_seconds) << " of CPU)";
    if (completed && level + 1 < n_levels) {
      bool measured = false;
      const int next_vertices = levels[level + 1].n_vertices;
      const double next = expected_seconds(timings, next_vertices, &measured);
      log << "; level " << level + 1 << " (" << next_vertices << " vertices) should take about "
          << duration_text(next)
          << (measured ? " (cost order measured on the levels before)"
                       : " (cost order 1.5 assumed)");
    }
    log << std::endl;
    study.levels.push_back(std::move(l));
    if (!completed) {
      study.failure = "level " + std::to_string(level) + ": " + failure;
      log << "  " << backend.name << ": convergence study stopped at " << study.failure << "\n";
      return study;
    }
  }
  study.completed = true;
  return study;
}

}  // namespace

CaseParameters convergence_level_parameters(const CaseParameters& base, int level, double ratio) {
  CaseParameters p = base;
  const double factor = std::pow(ratio, -level);
  p.garment.mesh_scale *= factor;
  p.garment.spacing.along_x_m *= factor;  // Mesh scale was applied when the file was read
  p.garment.spacing.along_y_m *= factor;
  p.garment.spacing.pattern_edge_length_m *= factor;  // a pattern's own edge length; 0 if none
  p.output.write_vtu = false;
  return p;
}

bool ConvergenceStudy::completed() const {
  return std::all_of(backends.begin(), backends.end(),
                     [](const BackendConvergence& b) { return b.completed; });
}

std::vector<ConvergenceSummaryRow> summarise_convergence(const BackendConvergence& study) {
  std::vector<ConvergenceSummaryRow> rows;
  std::size_t n_steps = 0;
  for (const ConvergenceLevel& l : study.levels) n_steps = std::max(n_steps, l.run.steps.size());
  for (std::size_t step = 0; step < n_steps; ++step) {
    // Levels are coarse to fine; a step counts on the levels that finished it.
    std::vector<double> pressures_Pa, edges_m;
    for (const ConvergenceLevel& l : study.levels)
      if (step < l.run.steps.size()) {
        pressures_Pa.push_back(l.run.steps[step].p_mean_Pa());
        edges_m.push_back(l.edge_m);
      }
    if (pressures_Pa.size() < 2) continue;
    const std::size_t n = pressures_Pa.size();
    const double ratio = measured_refinement_ratio(edges_m);

    const StepMeasurement& fine = study.levels[n - 1].run.steps[step];
    ConvergenceSummaryRow row;
    row.backend = study.backend;
    row.step = fine.step;
    row.alpha = fine.alpha;
    row.edge_fine_m = edges_m.back();
    row.ratio = ratio;
    row.p_fine_Pa = pressures_Pa.back();
    row.p_theory_Pa = fine.p_theory_Pa;
    row.estimate = estimate_convergence(
        pressures_Pa, ratio, formal_order,
        has_closed_form(fine.p_theory_Pa) ? std::optional<double>(fine.p_theory_Pa) : std::nullopt);
    row.rel_error_fine = relative(row.p_fine_Pa, row.p_theory_Pa);
    row.rel_error_richardson = relative(row.estimate.extrapolated, row.p_theory_Pa);
    rows.push_back(row);
  }
  return rows;
}

std::vector<RegionConvergenceRow> summarise_region_convergence(
    const BackendConvergence& study, const std::vector<std::string>& regions) {
  std::vector<RegionConvergenceRow> rows;
  std::size_t n_steps = 0;
  for (const ConvergenceLevel& l : study.levels)
    n_steps = std::max(n_steps, l.region_pressures.size());
  for (std::size_t step = 0; step < n_steps; ++step) {
    // Levels are coarse to fine; a step counts on the levels that finished it.
    std::vector<double> edges_m;
    std::vector<std::vector<RegionLevelPressure>> pressures;
    const ConvergenceLevel* finest = nullptr;
    for (const ConvergenceLevel& l : study.levels)
      if (step < l.region_pressures.size() && step < l.run.steps.size()) {
        edges_m.push_back(l.edge_m);
        std::vector<RegionLevelPressure> level;
        for (const RegionPressure& r : l.region_pressures[step])
          level.push_back({r.mean_Pa, r.peak_Pa});
        pressures.push_back(std::move(level));
        finest = &l;
      }
    if (pressures.size() < 2) continue;
    for (const RegionConvergence& r :
         estimate_region_convergence(regions, edges_m, pressures, formal_order))
      rows.push_back(
          {study.backend, finest->run.steps[step].step, finest->run.steps[step].alpha, r});
  }
  return rows;
}

ConvergenceStudy run_convergence_study(const CaseParameters& parameters,
                                       const ConvergenceSettings& settings,
                                       const std::vector<NamedBackendFactory>& backends,
                                       const std::string& output_dir, std::ostream& log) {
  namespace fs = std::filesystem;
  const int n_levels = settings.n_levels;
  if (n_levels < 2)
    throw std::invalid_argument("a convergence study needs at least two levels, not " +
                                std::to_string(n_levels));
  if (!(settings.ratio > 1.0) || !std::isfinite(settings.ratio))
    throw std::invalid_argument("the refinement ratio of a convergence study must exceed 1, not " +
                                std::to_string(settings.ratio));
  ConvergenceStudy result;
  StudyTables tables;
  tables.region_indices = chosen_regions(parameters, settings.regions, &result.regions);
  // Every level's scenario is made (and so checked) before any runs, so a bad mesh scale does
  // not surface after the coarse levels have run for minutes; each backend then runs these
  // same scenarios (convergence_run.h).
  std::vector<MadeLevel> levels;
  for (int level = 0; level < n_levels; ++level) {
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = process_cpu_seconds();
    MadeLevel made;
    made.scenario = make_scenario(convergence_level_parameters(parameters, level, settings.ratio));
    ++result.scenarios_made;
    made.n_vertices = made.scenario->mesh.n_vertices;
    made.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    made.cpu_seconds = process_cpu_seconds() - cpu_start;
    levels.push_back(std::move(made));
  }
  if (settings.on_levels_made) settings.on_levels_made(*levels.front().scenario);
  print_level_sizes(log, levels);

  // Under MPI every rank runs the study (the FE solves are distributed); the first writes the
  // tables, as run_scenario does for each level's own.
  std::optional<CsvTable> table, summary, region_table, region_summary;
  if (parameters.output.write_files && parameters.output.is_first_rank()) {
    const auto path = [&](const char* name) { return (fs::path(output_dir) / name).string(); };
    fs::create_directories(output_dir);
    table.emplace(path("convergence.csv"), convergence_columns());
    summary.emplace(path("convergence_summary.csv"), summary_columns());
    if (!result.regions.empty()) {
      region_table.emplace(path("convergence_regions.csv"), region_columns());
      region_summary.emplace(path("convergence_regions_summary.csv"), region_summary_columns());
    }
  }
  tables.levels = table ? &*table : nullptr;
  tables.regions = region_table ? &*region_table : nullptr;
  for (const NamedBackendFactory& backend : backends) {
    const bool last = &backend == &backends.back();
    result.backends.push_back(run_backend_levels(levels, backend, output_dir, tables, last, log));
    for (const ConvergenceSummaryRow& r : summarise_convergence(result.backends.back())) {
      const ConvergenceEstimate& e = r.estimate;
      if (summary)
        summary->write_row({r.backend, r.step, r.alpha, e.n_meshes, r.edge_fine_m, r.ratio,
                            r.p_fine_Pa, r.p_theory_Pa, e.order, e.order_observed ? 1 : 0,
                            e.extrapolated, e.gci_fine, e.safety_factor, r.rel_error_fine,
                            r.rel_error_richardson, e.error_order});
      result.summary.push_back(r);
    }
    for (const RegionConvergenceRow& row :
         summarise_region_convergence(result.backends.back(), result.regions)) {
      const RegionConvergence& r = row.estimate;
      if (region_summary)
        region_summary->write_row(
            {row.backend, row.step, row.alpha, r.region, r.n_levels, r.edge_fine_m, r.ratio,
             r.mean_fine_Pa, r.mean.order, r.mean.order_observed ? 1 : 0, r.mean.extrapolated,
             r.mean.gci_fine, r.peak_fine_Pa, r.peak.order, r.peak.order_observed ? 1 : 0,
             r.peak.extrapolated, r.peak.gci_fine, r.mean.safety_factor});
      result.region_summary.push_back(row);
    }
  }
  return result;
}

}  // namespace tightfit
