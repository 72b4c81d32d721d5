#include "app/region_comparison.h"

#include <cmath>
#include <fstream>
#include <map>
#include <stdexcept>
#include <vector>

namespace tightfit {

namespace {

// One CSV line's fields: quoted fields may hold commas, a doubled quote is one quote
// (io/csv_table.h writes them so).
std::vector<std::string> csv_fields(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      fields.back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      fields.emplace_back();
    } else if (c != '\r') {
      fields.back() += c;
    }
  }
  return fields;
}

struct RegionRow {
  double mean_Pa = NAN, peak_Pa = NAN;
};

// The last step's rows of a regions.csv, by region name in the file's order; `step` gets the
// step. Nothing when the file cannot be opened.
std::vector<std::pair<std::string, RegionRow>> last_step_rows(const std::string& path, int& step) {
  std::ifstream in(path);
  std::vector<std::pair<std::string, RegionRow>> rows;
  step = -1;
  if (!in) return rows;
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = csv_fields(line);
  std::map<std::string, std::size_t> column;
  for (std::size_t c = 0; c < header.size(); ++c) column[header[c]] = c;
  for (const char* name : {"step", "region", "p_mean_Pa", "p_peak_Pa"})
    if (!column.count(name))
      throw std::runtime_error(path + ": no column '" + name + "' in its header");
  const auto number = [](const std::string& text) {
    try {
      return text.empty() ? NAN : std::stod(text);
    } catch (const std::exception&) {
      return static_cast<double>(NAN);
    }
  };
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const std::vector<std::string> f = csv_fields(line);
    if (f.size() < header.size()) continue;
    const int row_step = static_cast<int>(number(f[column["step"]]));
    if (row_step != step) rows.clear(), step = row_step;
    rows.push_back(
        {f[column["region"]], {number(f[column["p_mean_Pa"]]), number(f[column["p_peak_Pa"]])}});
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
