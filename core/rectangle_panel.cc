#include "core/rectangle_panel.h"

#include "core/memory_budget.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace tightfit {

void MeshSpacing::validate() const {
  if (!(along_x_m > 0) || !(along_y_m > 0))
    throw std::invalid_argument("Garment/Edge length: both edge lengths must be positive (m)");
}

namespace {

// Joins two rows of vertices (sorted by x, same first and last x) by a strip of triangles,
// each step adding the shorter of the two possible diagonals (the Delaunay choice). On equal
// rows the two are equally long and the tie always advances the lower row first, so every
// cell is cut the same way.
void zip_rows(const std::vector<int>& lower, const std::vector<int>& upper,
              const std::vector<Vec2>& x, std::vector<Triangle>& triangles) {
  std::size_t a = 0, b = 0;
  while (a + 1 < lower.size() || b + 1 < upper.size()) {
    const bool advance_lower =
        b + 1 == upper.size() ||
        (a + 1 < lower.size() && (x[lower[a + 1]] - x[upper[b]]).squaredNorm() <=
                                     (x[lower[a]] - x[upper[b + 1]]).squaredNorm());
    if (advance_lower) {
      triangles.push_back({lower[a], lower[a + 1], upper[b]});
      ++a;
    } else {
      triangles.push_back({lower[a], upper[b + 1], upper[b]});
      ++b;
    }
  }
}

}  // namespace

Panel make_rectangle_panel(const std::string& name, double width_m, double height_m,
                           const MeshSpacing& spacing) {
  spacing.validate();
  if (!(width_m > 0) || !(height_m > 0))
    throw std::invalid_argument("panel '" + name + "': width and height must be positive (m)");
  // Counted in floating point first: a tiny edge length would overflow an int.
  const double cells_x = std::max(1.0, std::round(width_m / spacing.along_x_m));
  const double cells_y = std::max(1.0, std::round(height_m / spacing.along_y_m));
  char what[160];
  std::snprintf(what, sizeof what, "panel '%s' (%g x %g m at edge lengths %g x %g m)", name.c_str(),
                width_m, height_m, spacing.along_x_m, spacing.along_y_m);
  require_memory(std::string(what) + ": a run", (cells_x + 1) * (cells_y + 1), "vertices",
                 run_bytes_per_garment_vertex);
  const int nx = static_cast<int>(cells_x), ny = static_cast<int>(cells_y);
  const double dx = width_m / nx, dy = height_m / ny;

  Panel panel;
  panel.name = name;
  std::vector<std::vector<int>> rows(ny + 1);
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      rows[j].push_back(static_cast<int>(panel.rest_positions_m.size()));
      panel.rest_positions_m.emplace_back(i * dx, j * dy);
    }
  for (int j = 0; j < ny; ++j)
    zip_rows(rows[j], rows[j + 1], panel.rest_positions_m, panel.triangles);

  for (const auto& row : rows) {
    panel.edges["left"].push_back(row.front());
    panel.edges["right"].push_back(row.back());
  }
  panel.edges["bottom"] = rows.front();
  panel.edges["top"] = rows.back();
  return panel;
}

}  // namespace tightfit
