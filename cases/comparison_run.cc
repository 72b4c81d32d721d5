#include "cases/comparison_run.h"

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

// Largest |p_second - p_first| over the vertices either backend has in contact, Pa.
double largest_vertex_difference(const StepMeasurement& a, const StepMeasurement& b) {
  double largest = 0.0;
  for (std::size_t v = 0; v < a.field.pressure_Pa.size(); ++v)
    if (a.field.contact[v] || b.field.contact[v])
      largest = std::max(largest, std::abs(b.field.pressure_Pa[v] - a.field.pressure_Pa[v]));
  return largest;
}

}  // namespace

ComparisonResult run_comparison(Scenario& setup, const std::string& first_name,
                                const BackendFactory& make_first, const std::string& second_name,
                                const BackendFactory& make_second, const std::string& output_dir,
                                std::ostream& log) {
  namespace fs = std::filesystem;
  const auto path = [&](const std::string& name) { return (fs::path(output_dir) / name).string(); };
  ComparisonResult result;
  log << "Backend " << first_name << ":\n";
  result.first = run_scenario(setup, make_first, path(first_name), log);
  log << "Backend " << second_name << ":\n";
  result.second = run_scenario(setup, make_second, path(second_name), log);

  // As in run_scenario: the first rank writes the table and the collection, every rank
  // its piece of the difference surface when there are several.
  const OutputSettings& output = setup.parameters.output;
  const bool write_table = output.write_files && output.is_first_rank();
  const bool write_vtu = output.write_files && output.write_vtu;
  if (!write_table && !write_vtu) return result;
  fs::create_directories(output_dir);
  std::unique_ptr<CsvTable> table;
  std::unique_ptr<PvdWriter> series;
  if (write_table) {
    table = std::make_unique<CsvTable>(
        path("compare.csv"),
        std::vector<std::string>{
            "step", "alpha", "p_mean_Pa_" + first_name, "p_mean_Pa_" + second_name, "p_theory_Pa",
            "rel_diff", "p_std_Pa_" + first_name, "p_std_Pa_" + second_name,
            "rel_error_" + first_name, "rel_error_" + second_name, "max_vertex_diff_Pa"});
    if (write_vtu) series = std::make_unique<PvdWriter>(path("difference.pvd"));
  }
  const std::size_t n = std::min(result.first.steps.size(), result.second.steps.size());
  for (std::size_t i = 0; i < n; ++i) {
    const StepMeasurement& a = result.first.steps[i];
    const StepMeasurement& b = result.second.steps[i];
    const double rel_diff = a.p_mean_Pa() > 0 ? (b.p_mean_Pa() - a.p_mean_Pa()) / a.p_mean_Pa()
                                              : std::numeric_limits<double>::quiet_NaN();
    if (table)
      table->write_row({a.step, a.alpha, a.p_mean_Pa(), b.p_mean_Pa(), a.p_theory_Pa, rel_diff,
                        a.summary.std_Pa, b.summary.std_Pa, a.rel_error, b.rel_error,
                        largest_vertex_difference(a, b)});
    if (!write_vtu) continue;
    std::vector<double> difference(a.field.pressure_Pa.size());
    for (std::size_t v = 0; v < difference.size(); ++v)
      difference[v] = b.field.pressure_Pa[v] - a.field.pressure_Pa[v];
    SurfaceVtu vtu = garment_vtu(setup.mesh, b.state, b.field, b.alpha);
    vtu.add_point_scalar("pressure_Pa_" + first_name, a.field.pressure_Pa);
    vtu.add_point_scalar("pressure_difference_Pa", difference);
    char stem[64];
    std::snprintf(stem, sizeof stem, "difference_%04zu", i);
    const std::string file = write_vtu_share(vtu, output_dir, stem, output.rank, output.n_ranks);
    if (series) series->add(b.alpha, file);
  }
  return result;
}

}  // namespace tightfit
