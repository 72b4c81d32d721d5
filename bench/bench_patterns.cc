// Meshing time and element quality of the shipped pattern examples (docs/patterns.md): read,
// cut, divide the seams, mesh with CGAL's Delaunay mesher and sew, at a 10 mm target edge
// length and a 25-degree minimum angle. Counters: the mesh's vertices, its smallest angle
// (degrees) and the shortest, mean and longest triangle side (mm).
#include "pattern/pattern_file.h"
#include "pattern/pattern_garment.h"
#include "pattern/polygon_mesher.h"
#include "tests/pattern/aaron_bodice.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <string>

namespace {

using namespace tightfit;

const std::string patterns = TIGHTFIT_PATTERNS_DIR;
const std::string cases = TIGHTFIT_CASE_PATTERNS_DIR;

pattern::Pattern example(const std::string& which) {
  if (which == "aaron") return pattern::aaron_bodice(patterns);
  if (which == "dress")
    return pattern::read_pattern_file(patterns + "/garmentcode_dress_pencil_specification.json");
  if (which == "box") return pattern::read_pattern_file(patterns + "/clo_box_aama.dxf");
  return pattern::read_pattern_file(cases + "/curved_seam_tube.json");
}

void mesh_example(benchmark::State& state, const std::string& which) {
  const pattern::Pattern p = example(which);
  pattern::PatternMeshOptions options;
  options.edge_length_m = 0.01;
  Garment garment;
  for (auto _ : state) {
    garment = pattern::pattern_garment(p, options);
    benchmark::DoNotOptimize(garment);
  }
  const SimulationMesh mesh = weld(garment);
  double min_angle = 180, min_edge = 1e9, max_edge = 0, sum = 0;
  std::size_t triangles = 0;
  for (const Panel& panel : garment.panels) {
    const auto q = pattern::mesh_quality(panel.rest_positions_m, panel.triangles);
    min_angle = std::min(min_angle, q.min_angle_deg);
    min_edge = std::min(min_edge, q.min_edge_m);
    max_edge = std::max(max_edge, q.max_edge_m);
    sum += q.mean_edge_m * panel.triangles.size();
    triangles += panel.triangles.size();
  }
  state.counters["vertices"] = mesh.n_vertices;
  state.counters["min_angle_deg"] = min_angle;
  state.counters["edge_min_mm"] = 1e3 * min_edge;
  state.counters["edge_mean_mm"] = 1e3 * sum / triangles;
  state.counters["edge_max_mm"] = 1e3 * max_edge;
}

BENCHMARK_CAPTURE(mesh_example, aaron_bodice, std::string("aaron"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(mesh_example, garmentcode_dress, std::string("dress"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(mesh_example, clo_box_dxf, std::string("box"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(mesh_example, curved_seam_tube, std::string("tube"))
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
