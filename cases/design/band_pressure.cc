#include "cases/design/band_pressure.h"

#include "cases/region_pressure.h"

#include <stdexcept>

namespace tightfit {

std::vector<BandPressure> band_pressures(const SimulationMesh& mesh, const StepMeasurement& m,
                                         const std::vector<double>& heights_m,
                                         double band_width_m) {
  if (!m.holds_vertex_arrays())
    throw std::logic_error("band_pressures: the step no longer holds its pressure field");
  // Every welded vertex at its rest height (the layout's y), on the z axis of a scratch space.
  std::vector<Vec3> rest(mesh.n_vertices, Vec3::Zero());
  for (int u = 0; u < mesh.n_unwelded_vertices(); ++u)
    rest[mesh.welded_index[u]] = Vec3(0.0, 0.0, mesh.layout_positions_m[u].y());
  std::vector<BandPressure> bands;
  for (const double h : heights_m) {
    char text[120];
    std::snprintf(text, sizeof text, "band: slab z %.10g %.10g", h - 0.5 * band_width_m,
                  h + 0.5 * band_width_m);
    const BodyRegion band = parse_body_regions(text).front();
    const RegionPressure r = region_pressure(band, mesh.triangles, rest, m.field);
    bands.push_back({r.mean_Pa, r.peak_Pa});
  }
  return bands;
}

}  // namespace tightfit
