#include "cases/design/band_pressure.h"

#include "cases/region_pressure.h"

#include <cstdio>
#include <stdexcept>

namespace tightfit {

std::vector<BandPressure> band_pressures(const SimulationMesh& mesh, const StepMeasurement& m,
                                         const std::vector<double>& heights_m, double band_width_m,
                                         const Vec3& axis) {
  if (!m.holds_vertex_arrays())
    throw std::logic_error("band_pressures: the step no longer holds its pressure field");
  // Every welded vertex round the axis where it lies, at its rest height (the layout's y) along
  // it.
  const Vec3 a = axis.normalized();
  const std::vector<Vec3>& x = m.state.positions_m;
  std::vector<Vec3> rest(mesh.n_vertices, Vec3::Zero());
  for (int u = 0; u < mesh.n_unwelded_vertices(); ++u) {
    const int v = mesh.welded_index[u];
    rest[v] = x[v] - a.dot(x[v]) * a + mesh.layout_positions_m[u].y() * a;
  }
  std::vector<BandPressure> bands;
  for (const double h : heights_m) {
    char text[120];
    std::snprintf(text, sizeof text, "band: slab %.17g,%.17g,%.17g %.10g %.10g", a.x(), a.y(),
                  a.z(), h - 0.5 * band_width_m, h + 0.5 * band_width_m);
    const BodyRegion band = parse_body_regions(text).front();
    const RegionPressure r = region_pressure(band, mesh.triangles, rest, m.field);
    bands.push_back({r.mean_Pa, r.peak_Pa});
  }
  return bands;
}

}  // namespace tightfit
