#include "app/convergence_command.h"

#include "app/region_convergence_tables.h"
#include "app/run_command.h"
#include "app/summary_table.h"
#include "cases/case_parameters.h"
#include "cases/convergence_run.h"
#include "cases/scenario.h"
#include "core/backend_registry.h"
#include "core/closest_names.h"
#include "io/text_table.h"

#include <algorithm>
#include <ostream>
#include <stdexcept>

namespace tightfit {

namespace {

TextTable convergence_table(const ConvergenceStudy& study, int n_levels, double ratio) {
  TextTable table(
      "Mesh convergence of the mean pressure (" + std::to_string(n_levels) +
          " levels, edge divided by " + format_number(ratio, 4) +
          " each level; GCI of the finest, Roache 1994)",
      {"backend", "step", "alpha", "levels", "edge [mm]", "p fine [Pa]", "p Richardson [Pa]",
       "theory [Pa]", "order", "GCI [%]", "error fine [%]", "error Richardson [%]", "error order"});
  for (const ConvergenceSummaryRow& r : study.summary) {
    const ConvergenceEstimate& e = r.estimate;
    table.add_row(
        {r.backend, std::to_string(r.step), format_fixed(r.alpha, 3), std::to_string(e.n_meshes),
         format_fixed(1e3 * r.edge_fine_m, 2), format_fixed(r.p_fine_Pa, 2),
         format_fixed(e.extrapolated, 2), format_fixed(r.p_theory_Pa, 2),
         format_fixed(e.order, 2) + (e.order_observed ? "" : " (assumed)"),
         format_fixed(100.0 * e.gci_fine, 3), format_fixed(100.0 * r.rel_error_fine, 3),
         format_fixed(100.0 * r.rel_error_richardson, 3), format_fixed(e.error_order, 2)});
  }
  return table;
}

}  // namespace

int convergence_command(const CommandLine& cl, std::ostream& out) {
  CaseFile file;
  file.read(cl.case_files.front(), cl.overrides);
  CaseParameters parameters = file.parameters();
  share_output_by_rank(cl, parameters.output);
  const std::string dir =
      output_directory_for(cl, cl.case_files.front(), parameters.output.directory + "_convergence");
  std::vector<std::string> known;
  for (const BackendEntry& entry : backend_registry().entries()) known.push_back(entry.name);
  for (const std::string& name : cl.convergence_backends)
    if (std::find(known.begin(), known.end(), name) == known.end())
      throw std::invalid_argument("--backends: no backend '" + name + "'" +
                                  did_you_mean(name, known));
  std::vector<NamedBackendFactory> backends;
  for (const std::string& name : known) {
    const auto& chosen = cl.convergence_backends;
    if (!chosen.empty() && std::find(chosen.begin(), chosen.end(), name) == chosen.end()) continue;
    backends.push_back({name, [&file, name](const Problem& problem) {
                          return file.create_backend(name, problem);
                        }});
  }
  ConvergenceSettings settings;
  settings.n_levels = cl.levels;
  settings.ratio = cl.refinement_ratio;
  settings.regions = cl.convergence_regions;
  // The header is level 0's: the case's own scenario (but for VTU output), made once for the
  // study.
  settings.on_levels_made = [&](const Scenario& level_0) {
    print_case_header(out, cl.case_files.front(), level_0);
    out << "  convergence: " << cl.levels << " levels, mesh scale " << parameters.garment.mesh_scale
        << " divided by " << settings.ratio << " each level, on " << backends.size() << " backend"
        << (backends.size() == 1 ? "" : "s") << " (no VTU output)\n";
  };

  const ConvergenceStudy study = run_convergence_study(parameters, settings, backends, dir, out);
  out << "\n" << convergence_table(study, cl.levels, settings.ratio);
  for (const TextTable& table : region_convergence_tables(study)) out << "\n" << table;
  out << "  results in " << dir << "/ (convergence.csv, convergence_summary.csv"
      << (study.regions.empty() ? "" : ", convergence_regions.csv, convergence_regions_summary.csv")
      << ", <backend>/level_<k>/pressure.csv)\n";
  for (const BackendConvergence& b : study.backends)
    if (!b.completed) out << "  " << b.backend << " stopped early: " << b.failure << "\n";
  return study.completed() ? 0 : 1;
}

}  // namespace tightfit
