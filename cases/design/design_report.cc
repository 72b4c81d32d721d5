#include "cases/design/design_report.h"

#include "core/units.h"
#include "io/csv_table.h"

#include <cmath>
#include <stdexcept>

namespace tightfit {

namespace {

double mmHg(double Pa) {
  return units::to_mmHg(Pa);
}

// The check's bands, one per point, or none (no check, or it did not finish).
const std::vector<BandPressure>& checked_bands(const DesignProblem& problem,
                                               const DesignCheck& check) {
  if (!check.bands.empty() && check.bands.size() != problem.points.size())
    throw std::invalid_argument("the check on the " + check.backend + " backend measured " +
                                std::to_string(check.bands.size()) + " bands for " +
                                std::to_string(problem.points.size()) + " points");
  return check.bands;
}

}  // namespace

std::vector<std::string> check_outside(const DesignProblem& problem, const DesignCheck& check) {
  const std::vector<BandPressure>& bands = checked_bands(problem, check);
  std::vector<std::string> outside;
  for (std::size_t k = 0; k < bands.size(); ++k)
    if (!(std::abs(bands[k].mean_Pa - problem.targets_Pa[k]) <= check.tolerance_Pa))
      outside.push_back(problem.points[k].name);
  return outside;
}

void write_design_csv(const std::string& path, const DesignProblem& problem,
                      const DesignIteration& last, const DesignCheck& check) {
  const std::vector<BandPressure>& bands = checked_bands(problem, check);
  std::vector<std::string> columns = {"point",       "height_m",     "girth_m",   "circumference_m",
                                      "target_mmHg", "laplace_mmHg", "mean_mmHg", "peak_mmHg"};
  if (!bands.empty())
    columns.insert(columns.end(), {"check_mean_mmHg", "check_peak_mmHg", "check_error_mmHg"});
  CsvTable csv(path, columns);
  for (std::size_t k = 0; k < last.bands.size(); ++k) {
    const DesignBand& b = last.bands[k];
    std::vector<CsvCell> cells = {problem.points[k].name,
                                  problem.points[k].value,
                                  problem.girths_m[k],
                                  b.circumference_m,
                                  mmHg(problem.targets_Pa[k]),
                                  mmHg(b.laplace_Pa),
                                  mmHg(b.mean_Pa),
                                  mmHg(b.peak_Pa)};
    if (!bands.empty())
      cells.insert(cells.end(), {mmHg(bands[k].mean_Pa), mmHg(bands[k].peak_Pa),
                                 mmHg(bands[k].mean_Pa - problem.targets_Pa[k])});
    csv.write_row(cells);
  }
}

TextTable design_table(const std::string& title, const DesignProblem& problem,
                       const DesignIteration& last, const DesignCheck& check) {
  const std::vector<BandPressure>& bands = checked_bands(problem, check);
  std::vector<std::string> headers = {"point",         "H [m]",          "target",        "Laplace",
                                      "Laplace error", "simulated mean", "simulated peak"};
  if (!bands.empty())
    headers.insert(headers.end(),
                   {check.backend + " mean", check.backend + " peak", check.backend + " error"});
  TextTable table(title, headers);
  for (std::size_t k = 0; k < last.bands.size(); ++k) {
    const DesignBand& b = last.bands[k];
    std::vector<std::string> row = {problem.points[k].name,
                                    format_fixed(problem.points[k].value, 4),
                                    format_fixed(mmHg(problem.targets_Pa[k]), 2),
                                    format_fixed(mmHg(b.laplace_Pa), 2),
                                    format_fixed(mmHg(b.laplace_Pa - b.mean_Pa), 2),
                                    format_fixed(mmHg(b.mean_Pa), 2),
                                    format_fixed(mmHg(b.peak_Pa), 2)};
    if (!bands.empty())
      row.insert(row.end(),
                 {format_fixed(mmHg(bands[k].mean_Pa), 2), format_fixed(mmHg(bands[k].peak_Pa), 2),
                  format_fixed(mmHg(bands[k].mean_Pa - problem.targets_Pa[k]), 2)});
    table.add_row(row);
  }
  return table;
}

}  // namespace tightfit
