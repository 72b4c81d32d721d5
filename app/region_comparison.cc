#include "app/region_comparison.h"

#include "io/csv_reader.h"

#include <cmath>
#include <map>
#include <vector>

namespace tightfit {

namespace {

struct RegionRow {
  double mean_Pa = NAN, peak_Pa = NAN;
};

// The last step's rows of a regions.csv, by region name in the file's order; `step` gets the
// step. Nothing when the file cannot be opened.
std::vector<std::pair<std::string, RegionRow>> last_step_rows(const std::string& path, int& step) {
  std::vector<std::pair<std::string, RegionRow>> rows;
  step = -1;
  const std::optional<CsvRows> csv = CsvRows::read(path);
  if (!csv) return rows;
  const std::size_t step_column = csv->column("step"), region = csv->column("region"),
                    mean = csv->column("p_mean_Pa"), peak = csv->column("p_peak_Pa");
  for (std::size_t r = 0; r < csv->n_rows(); ++r) {
    const int row_step = static_cast<int>(csv->number(r, step_column));
    if (row_step != step) rows.clear(), step = row_step;
    rows.push_back({csv->text(r, region), {csv->number(r, mean), csv->number(r, peak)}});
  }
  return rows;
}

}  // namespace

std::optional<TextTable> region_comparison(const std::string& first_csv, const std::string& first,
                                           const std::string& second_csv,
                                           const std::string& second) {
  int first_step = -1, second_step = -1;
  const auto a = last_step_rows(first_csv, first_step);
  const auto b = last_step_rows(second_csv, second_step);
  if (a.empty() || b.empty() || first_step != second_step) return std::nullopt;
  std::map<std::string, RegionRow> by_name(b.begin(), b.end());
  TextTable table("Pressure by region, load step " + std::to_string(first_step) +
                      ": mean over the contact area and peak, " + first + " against " + second,
                  {"region", "p_mean " + first + " [Pa]", "p_mean " + second + " [Pa]",
                   "difference [%]", "p_peak " + first + " [Pa]", "p_peak " + second + " [Pa]"});
  for (const auto& [name, r] : a) {
    const RegionRow s = by_name.count(name) ? by_name[name] : RegionRow{};
    table.add_row({name, format_fixed(r.mean_Pa, 2), format_fixed(s.mean_Pa, 2),
                   format_fixed(100.0 * (s.mean_Pa - r.mean_Pa) / r.mean_Pa, 3),
                   format_fixed(r.peak_Pa, 2), format_fixed(s.peak_Pa, 2)});
  }
  return table;
}

}  // namespace tightfit
