// libFuzzer target: a pattern file (TIGHTFIT_FUZZ_EXTENSION: svg, json or dxf) read as
// `tightfit pattern` reads it (pattern/svg_reader.cc, garmentcode_reader.cc, dxf_reader.cc),
// checked, cut, and, when it passes, meshed at a coarse edge length and sewn. Any input must
// end in a garment or in an exception with a message, never a crash, a sanitizer report, a
// hang or a runaway allocation.
#include "pattern/pattern_file.h"
#include "pattern/pattern_garment.h"
#include "pattern/polygon_mesher.h"
#include "scratch_file.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <vector>

namespace {

// Meshing is the slow part: a panel of a kilometre (a number the fuzzer typed) at a
// centimetre's edge length would take minutes an input, not find more. The edge length grows
// with the largest panel (about 20 chords across it, 5 cm at least), and a pattern whose mesh
// would still hold more than this many vertices (counting every segment joint, which stays a
// vertex) is only read and checked. The program refuses such sizes by memory instead
// (pattern_garment's memory guard, tested by cli_pattern_too_fine_for_memory).
constexpr double max_fuzz_vertices = 5000;

// Each panel's bounding box, from its outline sampled 16 points a segment (curves bulge past
// their ends).
std::vector<tightfit::Vec2> panel_sizes_m(const tightfit::pattern::Pattern& cut) {
  std::vector<tightfit::Vec2> sizes;
  for (const auto& panel : cut.panels) {
    tightfit::Vec2 low = tightfit::Vec2::Constant(INFINITY), high = -low;
    for (const auto& edge : panel.edges)
      for (const auto& segment : edge.segments)
        for (int k = 0; k <= 16; ++k) {
          const tightfit::Vec2 x = tightfit::pattern::point_at(segment, k / 16.0);
          low = low.cwiseMin(x);
          high = high.cwiseMax(x);
        }
    sizes.push_back(high - low);
  }
  return sizes;
}

// The coarse edge length for `cut`, or 0 when its mesh would be too large to fuzz.
double coarse_edge_length_m(const tightfit::pattern::Pattern& cut) {
  const std::vector<tightfit::Vec2> sizes = panel_sizes_m(cut);
  double extent = 0.0;
  for (const tightfit::Vec2& size : sizes) extent = std::max(extent, size.maxCoeff());
  if (!std::isfinite(extent)) return 0.0;
  const double h = std::max(0.05, extent / 20);
  double vertices = 0.0;
  for (std::size_t p = 0; p < cut.panels.size(); ++p) {
    // Interior: the bounding box filled with equilateral triangles of side h.
    vertices += 2 * sizes[p].prod() / (std::sqrt(3.0) * h * h);
    for (const auto& edge : cut.panels[p].edges)
      vertices += tightfit::pattern::length_m(edge.segments) / h + edge.segments.size();
  }
  return std::isfinite(vertices) && vertices <= max_fuzz_vertices ? h : 0.0;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace pattern = tightfit::pattern;
  const std::string path = tightfit::fuzz::write_scratch_file(data, size, TIGHTFIT_FUZZ_EXTENSION);
  try {
    const pattern::Pattern p = pattern::read_pattern_file(path);
    pattern::validate(p);
    const pattern::Pattern cut = pattern::cut_pieces(p);
    pattern::seam_lengths(cut);
    pattern::PatternMeshOptions options;
    options.edge_length_m = coarse_edge_length_m(cut);
    if (options.edge_length_m == 0.0) return 0;
    const tightfit::Garment garment = pattern::pattern_garment(p, options);
    for (const auto& panel : garment.panels)
      pattern::mesh_quality(panel.rest_positions_m, panel.triangles);
    tightfit::weld(garment);
  } catch (const std::exception&) {
    // A refused pattern: what the program reports with exit status 2.
  }
  return 0;
}
