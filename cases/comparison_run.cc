#include "cases/comparison_run.h"

#include "io/csv_table.h"
#include "io/pvd_writer.h"
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

ComparisonResult run_comparison(CylinderSetup& setup, const std::string& first_name,
                                const BackendFactory& make_first, const std::string& second_name,
                                const BackendFactory& make_second, const std::string& output_dir,
                                std::ostream& log) {
  namespace fs = std::filesystem;
  const auto path = [&](const std::string& name) { return (fs::path(output_dir) / name).string(); };
  ComparisonResult result;
  log << "Backend " << first_name << ":\n";
  result.first = run_cylinder_case(setup, make_first, path(first_name), log);
  log << "Backend " << second_name << ":\n";
  result.second = run_cylinder_case(setup, make_second, path(second_name), log);

  if (!setup.parameters.output.write_files) return result;
  CsvTable table(path("compare.csv"),
                 {"step", "alpha", "p_mean_Pa_" + first_name, "p_mean_Pa_" + second_name,
                  "p_theory_Pa", "rel_diff", "p_std_Pa_" + first_name, "p_std_Pa_" + second_name,
                  "rel_error_" + first_name, "rel_error_" + second_name, "max_vertex_diff_Pa"});
  const bool write_vtu = setup.parameters.output.write_vtu;
  std::unique_ptr<PvdWriter> series;
  if (write_vtu) series = std::make_unique<PvdWriter>(path("difference.pvd"));
  const std::size_t n = std::min(result.first.steps.size(), result.second.steps.size());
  for (std::size_t i = 0; i < n; ++i) {
    const StepMeasurement& a = result.first.steps[i];
    const StepMeasurement& b = result.second.steps[i];
    const double rel_diff = a.p_mean_Pa() > 0 ? (b.p_mean_Pa() - a.p_mean_Pa()) / a.p_mean_Pa()
                                              : std::numeric_limits<double>::quiet_NaN();
    table.write_row({a.step, a.alpha, a.p_mean_Pa(), b.p_mean_Pa(), a.p_theory_Pa, rel_diff,
                     a.summary.std_Pa, b.summary.std_Pa, a.rel_error, b.rel_error,
                     largest_vertex_difference(a, b)});
    if (!write_vtu) continue;
    std::vector<double> difference(a.field.pressure_Pa.size());
    for (std::size_t v = 0; v < difference.size(); ++v)
      difference[v] = b.field.pressure_Pa[v] - a.field.pressure_Pa[v];
    SurfaceVtu vtu = garment_vtu(setup.mesh, b.state, b.field, b.alpha);
    vtu.add_point_scalar("pressure_Pa_" + first_name, a.field.pressure_Pa);
    vtu.add_point_scalar("pressure_difference_Pa", difference);
    char name[64];
    std::snprintf(name, sizeof name, "difference_%04zu.vtu", i);
    vtu.write(path(name));
    series->add(b.alpha, name);
  }
  return result;
}

}  // namespace tightfit
