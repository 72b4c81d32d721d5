// What the pattern fuzz targets (fuzz_pattern_file.cc) do with each input, kept apart so
// that the regression test of their findings (tests/pattern/test_pattern_hostile_input.cc)
// does the same: read the file as `tightfit pattern` does (a graded file's first size), check
// and cut it, then mesh and sew it at a coarse edge length.
#pragma once

#include "pattern/pattern_file.h"
#include "pattern/pattern_garment.h"
#include "pattern/polygon_mesher.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace tightfit::pattern::fuzz {

// Meshing is the slow part: a panel of a kilometre (a number the fuzzer typed) at a
// centimetre's edge length would take minutes an input, not find more. The edge length grows
// with the largest panel (about 20 chords across it, 5 cm at least), and a pattern whose mesh
// would still hold more than this many vertices (counting every segment joint, which stays a
// vertex) is only read and checked. The program refuses such sizes by memory instead
// (pattern_garment's memory guard, tested by cli_pattern_too_fine_for_memory).
inline constexpr double max_fuzz_vertices = 5000;

// Each panel's bounding box, from its outline sampled 16 points a segment (curves bulge past
// their ends).
inline std::vector<Vec2> panel_sizes_m(const Pattern& cut) {
  std::vector<Vec2> sizes;
  for (const auto& panel : cut.panels) {
    Vec2 low = Vec2::Constant(INFINITY), high = -low;
    for (const auto& edge : panel.edges)
      for (const auto& segment : edge.segments)
        for (int k = 0; k <= 16; ++k) {
          const Vec2 x = point_at(segment, k / 16.0);
          low = low.cwiseMin(x);
          high = high.cwiseMax(x);
        }
    sizes.push_back(high - low);
  }
  return sizes;
}

// The coarse edge length for `cut`, or 0 when its mesh would be too large to fuzz.
inline double coarse_edge_length_m(const Pattern& cut) {
  const std::vector<Vec2> sizes = panel_sizes_m(cut);
  double extent = 0.0;
  for (const Vec2& size : sizes) extent = std::max(extent, size.maxCoeff());
  if (!std::isfinite(extent)) return 0.0;
  const double h = std::max(0.05, extent / 20);
  double vertices = 0.0;
  for (std::size_t p = 0; p < cut.panels.size(); ++p) {
    // Interior: the bounding box filled with equilateral triangles of side h.
    vertices += 2 * sizes[p].prod() / (std::sqrt(3.0) * h * h);
    for (const auto& edge : cut.panels[p].edges)
      vertices += length_m(edge.segments) / h + edge.segments.size();
  }
  return std::isfinite(vertices) && vertices <= max_fuzz_vertices ? h : 0.0;
}

// Throws what the program would report (exit status 2); returns whether the pattern was
// meshed (false: too large to mesh while fuzzing, read and checked only).
inline bool read_check_mesh_and_sew(const std::string& path) {
  // A graded file: its first size, so that the pieces behind the size check are read too.
  PatternFileOptions options_of_file;
  const std::vector<std::string> sizes = pattern_file_sizes(path);
  if (sizes.size() > 1) options_of_file.size = sizes.front();
  const Pattern p = read_pattern_file(path, options_of_file);
  validate(p);
  const Pattern cut = cut_pieces(p);
  seam_lengths(cut);
  PatternMeshOptions options;
  options.edge_length_m = coarse_edge_length_m(cut);
  if (options.edge_length_m == 0.0) return false;
  const Garment garment = pattern_garment(p, options);
  for (const auto& panel : garment.panels) mesh_quality(panel.rest_positions_m, panel.triangles);
  weld(garment);
  return true;
}

}  // namespace tightfit::pattern::fuzz
