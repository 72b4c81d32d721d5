// SurfaceVtu::piece: one block of triangles of a surface, as a surface of its own.
#include "io/vtu_writer.h"

#include <stdexcept>

namespace tightfit {

SurfaceVtu SurfaceVtu::piece(std::size_t first_triangle, std::size_t end_triangle) const {
  if (first_triangle > end_triangle || end_triangle > triangles_.size())
    throw std::invalid_argument("VTU output: triangles [" + std::to_string(first_triangle) + ", " +
                                std::to_string(end_triangle) + ") are not within a surface of " +
                                std::to_string(triangles_.size()) + " triangles");

  // Points keep their relative order, so a piece reads like the matching part of the whole.
  constexpr int unused = -1;
  std::vector<int> new_index(points_m_.size(), unused);
  for (std::size_t k = first_triangle; k < end_triangle; ++k)
    for (int v : triangles_[k]) new_index[v] = 0;
  std::vector<int> old_index;
  for (std::size_t v = 0; v < points_m_.size(); ++v)
    if (new_index[v] != unused) {
      new_index[v] = static_cast<int>(old_index.size());
      old_index.push_back(static_cast<int>(v));
    }

  std::vector<Vec3> points_m;
  points_m.reserve(old_index.size());
  for (int v : old_index) points_m.push_back(points_m_[v]);
  std::vector<Triangle> triangles;
  triangles.reserve(end_triangle - first_triangle);
  for (std::size_t k = first_triangle; k < end_triangle; ++k) {
    const Triangle& t = triangles_[k];
    triangles.push_back({new_index[t[0]], new_index[t[1]], new_index[t[2]]});
  }

  SurfaceVtu part(std::move(points_m), std::move(triangles));
  for (const PointArray& a : point_arrays_) {
    PointArray restricted{a.name, a.n_components, a.is_flag, {}};
    restricted.values.reserve(old_index.size() * a.n_components);
    for (int v : old_index)
      for (int c = 0; c < a.n_components; ++c)
        restricted.values.push_back(a.values[static_cast<std::size_t>(v) * a.n_components + c]);
    part.point_arrays_.push_back(std::move(restricted));
  }
  part.field_values_ = field_values_;
  return part;
}

}  // namespace tightfit
