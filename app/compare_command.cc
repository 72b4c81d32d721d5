#include "app/compare_command.h"

#include "app/region_comparison.h"
#include "app/run_command.h"
#include "app/summary_table.h"
#include "cases/case_parameters.h"
#include "cases/comparison_run.h"
#include "core/backend_registry.h"

#include <ostream>

namespace tightfit {

int compare_command(const CommandLine& cl, std::ostream& out) {
  CaseFile file;
  file.read(cl.case_files.front(), cl.overrides);
  CaseParameters parameters = file.parameters();
  share_output_by_rank(cl, parameters.output);
  auto setup = make_scenario(parameters);
  const std::string dir = output_directory_for(cl, cl.case_files.front(),
                                               setup->parameters.output.directory + "_compare");
  const auto& entries = backend_registry().entries();
  const std::string first = entries.at(0).name, second = entries.at(1).name;
  const auto factory = [&](const std::string& name) -> BackendFactory {
    return [&file, name](const Problem& problem) { return file.create_backend(name, problem); };
  };
  print_case_header(out, cl.case_files.front(), *setup);
  const ComparisonResult result =
      run_comparison(*setup, first, factory(first), second, factory(second), dir, out);

  TextTable table("Cross-backend comparison: " + first + " against " + second + " (same mesh)",
                  {"step", "alpha", "p " + first + " [Pa]", "p " + second + " [Pa]", "theory [Pa]",
                   "difference [%]"});
  const std::size_t n = std::min(result.first.steps.size(), result.second.steps.size());
  for (std::size_t i = 0; i < n; ++i) {
    const StepMeasurement& a = result.first.steps[i];
    const StepMeasurement& b = result.second.steps[i];
    const double diff =
        a.p_mean_Pa() > 0 ? 100.0 * (b.p_mean_Pa() - a.p_mean_Pa()) / a.p_mean_Pa() : NAN;
    table.add_row({std::to_string(a.step), format_fixed(a.alpha, 3), format_fixed(a.p_mean_Pa(), 2),
                   format_fixed(b.p_mean_Pa(), 2), format_fixed(a.p_theory_Pa, 2),
                   format_fixed(diff, 3)});
  }
  out << "\n"
      << table << "  results in " << dir << "/ (compare.csv, " << first << "/, " << second
      << "/, difference.pvd)\n";
  // Both runs from the same start: the regions side by side (when the case lists them).
  if (const std::optional<TextTable> regions = region_comparison(
          dir + "/" + first + "/regions.csv", first, dir + "/" + second + "/regions.csv", second))
    out << "\n" << *regions;
  for (const RunResult* r : {&result.first, &result.second})
    if (!r->completed) out << "  " << r->backend << " stopped early: " << r->failure << "\n";
  return result.completed() ? 0 : 1;
}

}  // namespace tightfit
