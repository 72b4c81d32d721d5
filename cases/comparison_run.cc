#include "cases/comparison_run.h"

#include "core/mesh_geometry.h"
#include "io/csv_table.h"
#include "io/pvd_writer.h"
#include "io/vtu_share.h"
#include "io/vtu_writer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <ostream>

namespace tightfit {

namespace {

// What the comparison reads of a step of the first backend once the second has reached it: each
// vertex's pressure and contact flag (9 bytes a vertex, where the whole step holds about 140).
struct VertexPressures {
  std::vector<double> pressure_Pa;
  std::vector<char> contact;
};

// Largest |p_second - p_first| over the vertices either backend has in contact, Pa.
double largest_vertex_difference(const VertexPressures& a, const PressureField& b) {
  double largest = 0.0;
  for (std::size_t v = 0; v < a.pressure_Pa.size(); ++v)
    if (a.contact[v] || b.contact[v])
      largest = std::max(largest, std::abs(b.pressure_Pa[v] - a.pressure_Pa[v]));
  return largest;
}

}  // namespace

ComparisonResult run_comparison(Scenario& setup, const std::string& first_name,
                                const BackendFactory& make_first, const std::string& second_name,
                                const BackendFactory& make_second, const std::string& output_dir,
                                std::ostream& log) {
  namespace fs = std::filesystem;
  const auto path = [&](const std::string& name) { return (fs::path(output_dir) / name).string(); };
  // As in run_scenario: the first rank writes the table and the collection, every rank
  // its piece of the difference surface when there are several.
  const OutputSettings& output = setup.parameters.output;
  const bool write_table = output.write_files && output.is_first_rank();
  const bool write_vtu = output.write_files && output.write_vtu;

  ComparisonResult result;
  // The first backend's run keeps no step's per-vertex arrays (scenario_run.h): the comparison
  // keeps the pressures it needs of each step until the second backend has reached it.
  std::vector<VertexPressures> first_pressures;
  log << "Backend " << first_name << ":\n";
  result.first =
      run_scenario(setup, make_first, path(first_name), log, [&](const StepMeasurement& a) {
        if (write_table || write_vtu)
          first_pressures.push_back({a.field.pressure_Pa, a.field.contact});
      });

  std::unique_ptr<CsvTable> table;
  std::unique_ptr<PvdWriter> series;
  if (write_table || write_vtu) fs::create_directories(output_dir);
  if (write_table) {
    table = std::make_unique<CsvTable>(
        path("compare.csv"),
        std::vector<std::string>{
            "step", "alpha", "p_mean_Pa_" + first_name, "p_mean_Pa_" + second_name, "p_theory_Pa",
            "rel_diff", "p_std_Pa_" + first_name, "p_std_Pa_" + second_name,
            "rel_error_" + first_name, "rel_error_" + second_name, "max_vertex_diff_Pa"});
    if (write_vtu) series = std::make_unique<PvdWriter>(path("difference.pvd"));
  }
  // Each step of the second backend is compared with the first's as soon as it finishes.
  std::size_t i = 0;
  const auto compare_step = [&](const StepMeasurement& b) {
    const std::size_t step = i++;
    if (step >= first_pressures.size()) return;
    const StepMeasurement& a = result.first.steps[step];
    VertexPressures& pa = first_pressures[step];
    const double rel_diff = a.p_mean_Pa() > 0 ? (b.p_mean_Pa() - a.p_mean_Pa()) / a.p_mean_Pa()
                                              : std::numeric_limits<double>::quiet_NaN();
    if (table)
      table->write_row({a.step, a.alpha, a.p_mean_Pa(), b.p_mean_Pa(), a.p_theory_Pa, rel_diff,
                        a.summary.std_Pa, b.summary.std_Pa, a.rel_error, b.rel_error,
                        largest_vertex_difference(pa, b.field)});
    if (write_vtu) {
      std::vector<double> difference(pa.pressure_Pa.size());
      for (std::size_t v = 0; v < difference.size(); ++v)
        difference[v] = b.field.pressure_Pa[v] - pa.pressure_Pa[v];
      SurfaceVtu vtu =
          garment_vtu(setup.mesh, b.state, b.field,
                      vertex_principal_stretches(setup.mesh, b.state.positions_m), b.alpha);
      vtu.add_point_scalar("pressure_Pa_" + first_name, pa.pressure_Pa);
      vtu.add_point_scalar("pressure_difference_Pa", difference);
      char stem[64];
      std::snprintf(stem, sizeof stem, "difference_%04zu", step);
      const std::string file = write_vtu_share(vtu, output_dir, stem, output.rank, output.n_ranks);
      if (series) series->add(b.alpha, file);
    }
    pa = VertexPressures{};  // compared: no longer needed
  };
  log << "Backend " << second_name << ":\n";
  result.second = run_scenario(setup, make_second, path(second_name), log, compare_step);
  return result;
}

}  // namespace tightfit
