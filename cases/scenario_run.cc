#include "cases/scenario_run.h"

#include "core/step_heartbeat.h"

#include "cases/body_surface_pressure.h"
#include "core/interruption.h"
#include "core/mesh_geometry.h"
#include "core/units.h"
#include "io/csv_table.h"
#include "io/paraview_view_script.h"
#include "io/pvd_writer.h"
#include "io/vtu_share.h"
#include "io/vtu_writer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <ostream>

namespace tightfit {

std::vector<std::string> pressure_table_columns() {
  return {"step",
          "alpha",
          "p_mean_Pa",
          "p_std_Pa",
          "p_theory_Pa",
          "rel_error",
          "p_mean_gf_cm2",
          "p_mean_mmHg",
          "contact_fraction",
          "p_min_Pa",
          "p_max_Pa",
          "friction_max_Pa",
          "vertex_area",
          "pressure_definition",
          "iterations",
          "residual_N",
          "wall_time_s"};
}

namespace {

std::vector<CsvCell> pressure_row(const StepMeasurement& m) {
  const PressureSummary& s = m.summary;
  double friction_max_Pa = 0.0;
  for (std::size_t v = 0; v < m.field.friction_traction_Pa.size(); ++v)
    if (m.field.contact[v])
      friction_max_Pa = std::max(friction_max_Pa, m.field.friction_traction_Pa[v]);
  std::vector<CsvCell> row{m.step,
                           m.alpha,
                           s.mean_Pa,
                           s.std_Pa,
                           m.p_theory_Pa,
                           m.rel_error,
                           units::to_gf_per_cm2(s.mean_Pa),
                           units::to_mmHg(s.mean_Pa),
                           s.contact_fraction,
                           s.min_Pa,
                           s.max_Pa,
                           friction_max_Pa,
                           to_string(m.field.area_definition),
                           to_string(m.field.definition),
                           m.report.iterations,
                           m.report.residual_N,
                           m.report.wall_seconds};
  for (double value : m.extra_values) row.emplace_back(value);
  return row;
}

void print_progress(std::ostream& log, const StepMeasurement& m, std::size_t n_steps) {
  char line[256];
  std::snprintf(line, sizeof line, "  step %2d/%zu  alpha %.3f  p %8.2f Pa (%6.3f gf/cm2)", m.step,
                n_steps - 1, m.alpha, m.p_mean_Pa(), units::to_gf_per_cm2(m.p_mean_Pa()));
  log << line;
  if (std::isfinite(m.p_theory_Pa)) {
    std::snprintf(line, sizeof line, "  theory %8.2f Pa", m.p_theory_Pa);
    log << line;
  }
  if (std::isfinite(m.rel_error)) {
    std::snprintf(line, sizeof line, " (%+6.2f%%)", 100.0 * m.rel_error);
    log << line;
  }
  std::snprintf(line, sizeof line, "  %d it  %.2f s", m.report.iterations, m.report.wall_seconds);
  log << line << std::endl;
}

// What the run's ParaView view needs to know (io/paraview_view_script.h): the unit is mmHg in a
// medical case (one that classes its compression), the angular profile is the angular profile
// measurement's, the front looks along +y with the protocol's up (bodies face -y, docs/bodies.md).
ViewScriptSettings view_script_settings(const Scenario& scenario) {
  const CaseParameters& p = scenario.parameters;
  ViewScriptSettings s;
  s.title = p.garment.name + " on " + scenario.body->body().name();
  s.body_has_pressure = p.output.body_pressure;
  for (const NamedMeasurement& m : p.measurements) {
    if (m.kind == "compression class") s.in_mmHg = true;
    if (m.kind == "angular profile") s.angular_profile_csv = "pressure_theta.csv";
  }
  s.view_up = p.protocol.up;
  if (p.body.kind == "plane") {
    // A sheet on a plane is seen from above: from the front it is a line.
    s.view_direction = -p.protocol.up;
    s.view_up = p.protocol.up.unitOrthogonal();
  } else if (!(s.view_direction.cross(s.view_up).norm() > 1e-6 * s.view_up.norm())) {
    s.view_direction = s.view_up.unitOrthogonal();
  }
  return s;
}

}  // namespace

RunResult run_scenario(Scenario& scenario, const BackendFactory& make_backend,
                       const std::string& output_dir, std::ostream& log,
                       const StepObserver& on_step) {
  namespace fs = std::filesystem;
  const OutputSettings& output = scenario.parameters.output;
  // Every rank holds the whole result's scalars (the steps' per-vertex arrays are released
  // once written, scenario_run.h). The first writes the tables and the collections, the last
  // the body; the garment is written by every rank, one piece each, when there are several.
  const bool write_tables = output.write_files && output.is_first_rank();
  const bool write_garment = output.write_files && output.write_vtu;
  const bool write_series = write_tables && output.write_vtu;  // .pvd collections
  // The body VTU is the last rank's: the first holds the larger share of MUMPS's factors
  // (docs/performance.md). Its pressure map is every rank's work, each searching its block of
  // the garment (cases/body_surface_pressure.h).
  const bool write_body =
      output.write_files && output.write_vtu && output.rank == output.n_ranks - 1;
  const bool map_body = output.write_files && output.write_vtu && output.body_pressure;
  if (write_tables || write_garment) fs::create_directories(output_dir);
  const auto path = [&](const std::string& name) { return (fs::path(output_dir) / name).string(); };

  RunResult result;
  const Measurements measurements = make_measurements(scenario.parameters);
  result.columns = measurement_columns(measurements);
  const RunFiles files{output_dir, write_tables};
  std::unique_ptr<Backend> backend = make_backend(scenario.problem);
  result.backend = backend->name();
  scenario.prepare_step(0);
  for (const auto& measurement : measurements) measurement->prepare(scenario);
  backend->set_positions(scenario.initial_positions());

  // Opening the files is this rank's alone: under MPI the others must not be left waiting.
  std::unique_ptr<CsvTable> table;
  std::ofstream solver_log;
  std::unique_ptr<PvdWriter> garment_series, body_series;
  output.on_this_rank([&] {
    if (write_tables) {
      std::vector<std::string> columns = pressure_table_columns();
      columns.insert(columns.end(), result.columns.begin(), result.columns.end());
      table = std::make_unique<CsvTable>(path("pressure.csv"), columns);
      // The solver's own account of each step (Newton residuals and Krylov iterations, RK4
      // frames and time step), which the progress line only counts.
      solver_log.open(path("solver.log"));
      solver_log << "# " << result.backend << ": the solver's report of each load step\n";
    }
    if (write_series) {
      garment_series = std::make_unique<PvdWriter>(path("garment.pvd"));
      body_series = std::make_unique<PvdWriter>(path("body.pvd"));
      write_paraview_view_script(path("view.py"), view_script_settings(scenario));
    }
  });

  auto stop = [&](const std::string& why) {
    result.failure = why;
    log << "  stopped: " << why << std::endl;
    if (solver_log.is_open()) solver_log << "stopped: " << why << std::endl;
  };
  for (std::size_t step = 0; step < scenario.alphas.size(); ++step) {
    try {
      throw_if_interrupted(interruption_signal(), "before load step " + std::to_string(step));
      char what[64];
      std::snprintf(what, sizeof what, "step %zu/%zu (alpha %.3f)", step,
                    scenario.alphas.size() - 1, scenario.alphas[step]);
      const StepHeartbeat heartbeat(log, what);
      result.steps.push_back(
          solve_and_measure(scenario, *backend, static_cast<int>(step), measurements));
      // The step before is written and no one reads its arrays any more.
      if (result.steps.size() > 1) release_vertex_arrays(result.steps[result.steps.size() - 2]);
    } catch (const SolverError& e) {
      stop(e.what());
      break;
    } catch (const Interrupted& e) {
      result.interrupted_by = e.signal();
      stop(std::string(e.what()) + "; " +
           (step == 0 ? std::string("no load step had finished")
                      : "load steps 0 to " + std::to_string(step - 1) + " are written"));
      break;
    }
    const StepMeasurement& m = result.steps.back();
    // Writing is this rank's alone: under MPI the others must not be left waiting.
    output.on_this_rank([&] {
      if (table) table->write_row(pressure_row(m));
      for (const auto& measurement : measurements) measurement->after_step(scenario, m, files);
      if (solver_log.is_open())
        solver_log << "step " << m.step << ", alpha " << m.alpha << ": " << m.report.text()
                   << std::endl;
      if (write_garment) {
        char stem[64];
        std::snprintf(stem, sizeof stem, "garment_%04zu", step);
        SurfaceVtu garment =
            garment_vtu(scenario.mesh, m.state, m.field,
                        vertex_principal_stretches(scenario.mesh, m.state.positions_m), m.alpha);
        for (const auto& [array_name, values] : backend->extra_point_data())
          garment.add_point_scalar(array_name, values);
        // The first rank lists the step only after its own piece and the .pvtu header are on
        // disk; the other ranks' pieces may land a moment later (complete when the run ends).
        const std::string file =
            write_vtu_share(garment, output_dir, stem, output.rank, output.n_ranks);
        if (garment_series) garment_series->add(m.alpha, file);
      }
      char body_name[64];
      std::snprintf(body_name, sizeof body_name, "body_%04zu.vtu", step);
      if (map_body) {
        const BodySurfacePressure body =
            body_surface_pressure(scenario, m, RankShare{output.rank, output.n_ranks});
        if (write_body) body_pressure_vtu(body, m.field).write(path(body_name));
      } else if (write_body) {
        write_body_vtu(path(body_name), scenario.body->body().display_mesh());
      }
      // With several ranks the file may land a moment after it is listed, as the pieces do.
      if (write_series) body_series->add(m.alpha, body_name);
    });
    print_progress(log, m, scenario.alphas.size());
    if (on_step) on_step(m);
    // The other ranks' piece of the garment is on disk; the closing files are the first's.
    if (!output.is_first_rank()) release_vertex_arrays(result.steps.back());
  }
  for (const auto& measurement : measurements) {
    output.on_this_rank([&] { measurement->after_run(scenario, result.steps, files); });
    for (const std::string& f : measurement->file_names()) result.files.push_back(f);
    for (TextTable& t : measurement->summary_tables(scenario, result.steps))
      result.tables.push_back(std::move(t));
  }
  result.completed = result.failure.empty();
  return result;
}

}  // namespace tightfit
