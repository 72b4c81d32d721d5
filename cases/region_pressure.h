// The pressure the garment puts on a body region (docs/measurements.md, "Regions"), from the
// shared extractor's vertex pressures p_v and vertex areas A_v (contact/pressure_extractor.h).
//
// A vertex belongs to a region by the share w_v of its own area (its barycentric cell: the
// part of each adjacent triangle nearer its corner in barycentric terms) that lies in the
// region, sampled on a regular grid of sub-triangles, so that a region boundary cutting
// through the mesh counts the area on its own side and not whole cells:
//   contact area  A = sum over contact vertices of w_v A_v                   (m^2)
//   normal force  F = sum over contact vertices of w_v p_v A_v               (N)
//   mean pressure p_mean = F / A: the area-weighted mean over the contact area (Pa)
//   peak pressure p_peak = max p_v over contact vertices with w_v > 0         (Pa)
// A region the garment does not touch reads zero area and force and no mean or peak (NaN).
#pragma once

#include "cases/body_region.h"
#include "contact/pressure_extractor.h"

#include <vector>

namespace tightfit {

struct RegionPressure {
  double garment_area_m2 = 0.0;  // sum of w_v A_v over every vertex: the garment in the region
  int n_contact_vertices = 0;    // contact vertices with w_v > 0
  double contact_area_m2 = 0.0;
  double normal_force_N = 0.0;
  double mean_Pa = 0.0;  // NaN without contact
  double peak_Pa = 0.0;  // NaN without contact
};

// w_v of every vertex for `region`: the share of its barycentric cell inside it, 0 to 1.
std::vector<double> region_vertex_weights(const BodyRegion& region,
                                          const std::vector<Triangle>& triangles,
                                          const std::vector<Vec3>& positions_m);

RegionPressure region_pressure(const BodyRegion& region, const std::vector<Triangle>& triangles,
                               const std::vector<Vec3>& positions_m, const PressureField& field);

}  // namespace tightfit
