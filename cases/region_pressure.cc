#include "cases/region_pressure.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace tightfit {

namespace {

// Each triangle is first split into a regular grid of sub-triangles, samples_per_edge to an
// edge; a sub-triangle whose corners and centroid are not all on one side of the region's
// boundary is split in four again, up to `refinements` times, so that the boundary is placed
// to 1/96 of an edge (a slab's area is then within the mesh's own chord error on the meshes of
// cases/, docs/measurements.md). A region narrower than a sixth of an edge may be missed.
constexpr int samples_per_edge = 6;
constexpr int refinements = 4;

class CellSampler {
 public:
  CellSampler(const BodyRegion& region, std::vector<double>& inside, std::vector<double>& total)
      : region_(region), inside_(inside), total_(total) {}

  void sample_triangle(const Triangle& t, const std::array<Vec3, 3>& x) {
    t_ = t;
    x_ = x;
    const double area = 0.5 * (x[1] - x[0]).cross(x[2] - x[0]).norm();
    const double k = samples_per_edge;
    // The regular split in barycentric coordinates: corners (i, j), (i+1, j), (i, j+1) / k
    // pointing up and (i+1, j), (i+1, j+1), (i, j+1) / k pointing down.
    const auto corner = [&](int i, int j) { return Vec3(1.0 - (i + j) / k, i / k, j / k); };
    for (int i = 0; i < samples_per_edge; ++i)
      for (int j = 0; i + j < samples_per_edge; ++j) {
        sample({corner(i, j), corner(i + 1, j), corner(i, j + 1)}, area / (k * k), 0);
        if (i + j + 1 < samples_per_edge)
          sample({corner(i + 1, j), corner(i + 1, j + 1), corner(i, j + 1)}, area / (k * k), 0);
      }
  }

 private:
  bool inside(const Vec3& l) const {
    return region_.contains(l[0] * x_[0] + l[1] * x_[1] + l[2] * x_[2]);
  }
  // A sub-triangle with corners `l` (barycentric) and area `area`.
  void sample(const std::array<Vec3, 3>& l, double area, int depth) {
    const Vec3 centroid = (l[0] + l[1] + l[2]) / 3.0;
    const bool in = inside(centroid);
    if (depth < refinements && (inside(l[0]) != in || inside(l[1]) != in || inside(l[2]) != in)) {
      const Vec3 m01 = 0.5 * (l[0] + l[1]), m12 = 0.5 * (l[1] + l[2]), m20 = 0.5 * (l[2] + l[0]);
      for (const auto& child : {std::array<Vec3, 3>{l[0], m01, m20},
                                {m01, l[1], m12},
                                {m20, m12, l[2]},
                                {m01, m12, m20}})
        sample(child, 0.25 * area, depth + 1);
      return;
    }
    // The sample's area goes to the corner whose barycentric cell holds its centroid (the
    // largest coordinate; shared equally on a tie), so that on the regular grid each corner
    // receives exactly a third of the triangle.
    const double largest = centroid.maxCoeff();
    int n_largest = 0;
    for (int c = 0; c < 3; ++c) n_largest += centroid[c] > largest - 1e-12;
    for (int c = 0; c < 3; ++c) {
      if (centroid[c] <= largest - 1e-12) continue;
      total_[t_[c]] += area / n_largest;
      if (in) inside_[t_[c]] += area / n_largest;
    }
  }

  const BodyRegion& region_;
  std::vector<double>& inside_;
  std::vector<double>& total_;
  Triangle t_{};
  std::array<Vec3, 3> x_;
};

}  // namespace

std::vector<double> region_vertex_weights(const BodyRegion& region,
                                          const std::vector<Triangle>& triangles,
                                          const std::vector<Vec3>& positions_m) {
  const std::size_t n = positions_m.size();
  std::vector<double> inside(n, 0.0), total(n, 0.0);
  CellSampler sampler(region, inside, total);
  for (const Triangle& t : triangles)
    sampler.sample_triangle(t, {positions_m[t[0]], positions_m[t[1]], positions_m[t[2]]});
  std::vector<double> weights(n, 0.0);
  for (std::size_t v = 0; v < n; ++v)
    if (total[v] > 0)
      weights[v] = inside[v] / total[v];
    else  // a vertex of no triangle (or only degenerate ones): it is where it is
      weights[v] = region.contains(positions_m[v]) ? 1.0 : 0.0;
  return weights;
}

RegionPressure region_pressure(const BodyRegion& region, const std::vector<Triangle>& triangles,
                               const std::vector<Vec3>& positions_m, const PressureField& field) {
  const std::vector<double> w = region_vertex_weights(region, triangles, positions_m);
  RegionPressure r;
  r.peak_Pa = -std::numeric_limits<double>::infinity();
  for (std::size_t v = 0; v < w.size(); ++v) {
    r.garment_area_m2 += w[v] * field.vertex_area_m2[v];
    if (w[v] <= 0 || !field.contact[v]) continue;
    ++r.n_contact_vertices;
    r.contact_area_m2 += w[v] * field.vertex_area_m2[v];
    r.normal_force_N += w[v] * field.pressure_Pa[v] * field.vertex_area_m2[v];
    r.peak_Pa = std::max(r.peak_Pa, field.pressure_Pa[v]);
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  r.mean_Pa = r.contact_area_m2 > 0 ? r.normal_force_N / r.contact_area_m2 : nan;
  if (r.n_contact_vertices == 0) r.peak_Pa = nan;
  return r;
}

}  // namespace tightfit
