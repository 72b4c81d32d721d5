// The body query alone, per garment vertex, as the mass-spring backend asks it frame after
// frame (docs/performance-bodies.md, "Body queries"): each vertex keeps its near faces
// (RigidBody::query_near) and moves a little between frames. Bodies: the MakeHuman default
// female (26756 triangles) and the same surface with every triangle split in four at its
// edges' midpoints (107024 triangles), with the smooth contact surface that case files use
// and with the faceted one.
//
// - walk/*: 1312 points (the stocking's vertex count) within 0.2 mm of the surface, each
//   moved 5 um in a random direction per frame (a settling garment's frame moves less), one
//   query per point and frame; us_per_vertex is the time per vertex and frame. `all` asks the
//   whole answer (query_near), `force` what a mass-spring frame without friction asks
//   (query_parts without closest point, dn/dx and location), `fresh` query() (the tree every
//   time).
#include "bodies/mesh_body.h"

#include <benchmark/benchmark.h>

#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace {

using namespace tightfit;

const std::string female =
    std::string(TIGHTFIT_BODIES_DIR) + "/makehuman_default_female_body_m.obj";
constexpr int garment_vertices = 1312;

using Surface = MeshBodyOptions::ContactSurface;

// Each triangle split in four at its edges' midpoints (shared between the two triangles of an
// edge, so the surface stays closed): four times the triangles on the same flat faces.
TriangleSurface split_in_four(const TriangleSurface& in) {
  TriangleSurface out;
  out.vertices_m = in.vertices_m;
  std::map<std::pair<int, int>, int> midpoint;
  const auto middle = [&](int a, int b) {
    const std::pair<int, int> key = std::minmax(a, b);
    const auto found = midpoint.find(key);
    if (found != midpoint.end()) return found->second;
    out.vertices_m.push_back(0.5 * (in.vertices_m[a] + in.vertices_m[b]));
    const int index = static_cast<int>(out.vertices_m.size()) - 1;
    midpoint.emplace(key, index);
    return index;
  };
  for (const Triangle& t : in.triangles) {
    const int m01 = middle(t[0], t[1]), m12 = middle(t[1], t[2]), m20 = middle(t[2], t[0]);
    out.triangles.push_back({t[0], m01, m20});
    out.triangles.push_back({m01, t[1], m12});
    out.triangles.push_back({m20, m12, t[2]});
    out.triangles.push_back({m01, m12, m20});
  }
  return out;
}

std::unique_ptr<MeshBody> body(bool split, Surface surface) {
  MeshBodyOptions options;
  options.contact_surface = surface;
  const auto loaded = load_mesh_body(female, options);
  if (!split) return std::make_unique<MeshBody>(loaded->surface(), options);
  return std::make_unique<MeshBody>(split_in_four(loaded->surface()), options);
}

// Points within 0.2 mm of the surface, off random vertices along their normals and a little
// sideways.
std::vector<Vec3> points_on(const MeshBody& b) {
  std::mt19937 random(5);
  std::uniform_int_distribution<int> vertex(0, int(b.surface().vertices_m.size()) - 1);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<Vec3> points;
  for (int k = 0; k < garment_vertices; ++k) {
    const int v = vertex(random);
    points.push_back(b.surface().vertices_m[v] + 2e-4 * unit(random) * b.vertex_normals()[v] +
                     2e-3 * Vec3(unit(random), unit(random), unit(random)));
  }
  return points;
}

enum class Ask { all, force, fresh };

SurfacePoint ask(const MeshBody& b, const Vec3& x, NearFaces& near, Ask what) {
  if (what == Ask::fresh) return b.query(x);
  if (what == Ask::all) return b.query_near(x, near);
  QueryParts parts;
  parts.closest_point = parts.normal_derivative = parts.location = false;
  return b.query_parts(x, near, parts);
}

// One frame: every point moved by its step and asked once. Not inlined, so that callgrind can
// count a warm frame's instructions alone (--toggle-collect='*one_frame*').
__attribute__((noinline)) void one_frame(const MeshBody& b, std::vector<Vec3>& x,
                                         const std::vector<Vec3>& step,
                                         std::vector<NearFaces>& kept, Ask what) {
  for (std::size_t i = 0; i < x.size(); ++i) {
    x[i] += step[i];
    benchmark::DoNotOptimize(ask(b, x[i], kept[i], what));
  }
}

void walk(benchmark::State& state, bool split, Surface surface, Ask what) {
  const auto b = body(split, surface);
  std::vector<Vec3> x = points_on(*b);
  std::vector<NearFaces> kept(x.size());
  // A first, untimed query of each point fills its kept faces: the frames timed are warm.
  for (std::size_t i = 0; i < x.size(); ++i) ask(*b, x[i], kept[i], what);
  std::mt19937 random(9);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<Vec3> step(x.size());
  for (auto _ : state) {
    state.PauseTiming();
    for (Vec3& s : step) s = 5e-6 * Vec3(unit(random), unit(random), unit(random));
    state.ResumeTiming();
    one_frame(*b, x, step, kept, what);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long>(x.size()));
  state.counters["triangles"] = double(b->surface().triangles.size());
  state.counters["us_per_vertex"] =
      benchmark::Counter(double(state.iterations()) * double(x.size()) * 1e-6,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

}  // namespace

BENCHMARK_CAPTURE(walk, female_27k_smooth_all, false, Surface::smooth, Ask::all)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(walk, female_27k_smooth_force, false, Surface::smooth, Ask::force)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(walk, female_107k_smooth_all, true, Surface::smooth, Ask::all)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(walk, female_107k_smooth_force, true, Surface::smooth, Ask::force)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(walk, female_27k_faceted_all, false, Surface::faceted, Ask::all)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(walk, female_107k_faceted_all, true, Surface::faceted, Ask::all)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(walk, female_27k_smooth_fresh, false, Surface::smooth, Ask::fresh)
    ->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
