// Cost of the rigid bodies' queries and of building a mesh body's tree (docs/performance.md,
// "Bodies"): the MakeHuman default female (13378 quads, 26756 triangles) and the 754-face
// proxy, against the analytic cylinder.
//
// - query_*: one query (closest point, signed distance, normal, its derivative) per point, on
//   points scattered within 2 cm of the body's surface (a garment's vertices are there).
// - build_tree: CGAL's AABB tree and its distance-query kd-tree over the triangles.
// - morph_step: what a morphing body does between load steps: blend, check, normals, tree.
// - load: read the OBJ (VTK), import, check, normals, tree.
#include "bodies/cylinder.h"
#include "bodies/mesh_body.h"
#include "bodies/morphing_mesh_body.h"
#include "bodies/triangle_bvh.h"

#include <benchmark/benchmark.h>

#include <random>
#include <string>
#include <vector>

namespace {

using namespace tightfit;

const std::string bodies = TIGHTFIT_BODIES_DIR;
const std::string female = bodies + "/makehuman_default_female_body_m.obj";
const std::string male = bodies + "/makehuman_default_male_body_m.obj";
const std::string proxy = bodies + "/mh_proxy741_closed_m.obj";

// Vertices of the body moved along their normals by up to 2 cm either way.
std::vector<Vec3> points_near(const MeshBody& body, int n) {
  std::mt19937 random(11);
  std::uniform_int_distribution<int> vertex(0,
                                            static_cast<int>(body.surface().vertices_m.size()) - 1);
  std::uniform_real_distribution<double> offset(-0.02, 0.02);
  std::vector<Vec3> points;
  for (int k = 0; k < n; ++k) {
    const int v = vertex(random);
    points.push_back(body.surface().vertices_m[v] + offset(random) * body.vertex_normals()[v]);
  }
  return points;
}

void run_queries(benchmark::State& state, const RigidBody& body, const std::vector<Vec3>& points) {
  for (auto _ : state)
    for (const Vec3& x : points) benchmark::DoNotOptimize(body.query(x));
  state.SetItemsProcessed(state.iterations() * static_cast<long>(points.size()));
}

void query_mesh(benchmark::State& state, const std::string& path) {
  const auto body = load_mesh_body(path, {});
  run_queries(state, *body, points_near(*body, 10000));
  state.counters["triangles"] = body->surface().triangles.size();
}

void query_cylinder(benchmark::State& state) {
  const Cylinder cylinder(Vec3::Zero(), Vec3::UnitZ(), 0.05);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> u(-0.07, 0.07);
  std::vector<Vec3> points;
  for (int k = 0; k < 10000; ++k) points.emplace_back(u(random), u(random), u(random));
  run_queries(state, cylinder, points);
}

void build_tree(benchmark::State& state, const std::string& path) {
  const auto body = load_mesh_body(path, {});
  for (auto _ : state) {
    TriangleBvh tree;
    tree.build(body->surface().vertices_m, body->surface().triangles);
    benchmark::DoNotOptimize(tree);
  }
  state.counters["triangles"] = body->surface().triangles.size();
}

void morph_step(benchmark::State& state) {
  const auto body = load_morphing_mesh_body(female, male, {});
  double t = 0.0;
  for (auto _ : state) {
    t = t > 0.9 ? 0.0 : t + 0.1;
    body->set_morph(t);
  }
}

void load(benchmark::State& state, const std::string& path) {
  for (auto _ : state) benchmark::DoNotOptimize(load_mesh_body(path, {}));
}

}  // namespace

BENCHMARK_CAPTURE(query_mesh, female_13k_quads, female)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(query_mesh, proxy_754_faces, proxy)->Unit(benchmark::kMillisecond);
BENCHMARK(query_cylinder)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(build_tree, female_13k_quads, female)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(build_tree, proxy_754_faces, proxy)->Unit(benchmark::kMillisecond);
BENCHMARK(morph_step)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(load, female_13k_quads, female)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
