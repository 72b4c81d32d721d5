// The FE backend's weight: consistent nodal loads against the garment's mass (rest area times
// the areal density, computed by core/ from the triangles) and the mass-spring backend's lumped
// masses, and the equilibrium on a horizontal cylinder: the body carries the whole weight.
#include "core/mesh_geometry.h"
#include "fem/fem_backend.h"
#include "tube_problem.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>

namespace tightfit {
namespace {

using testing::TubeCase;

const MeshSpacing coarse{0.03, 0.06};

Vec3 sum(const std::vector<Vec3>& forces) {
  Vec3 total = Vec3::Zero();
  for (const Vec3& f : forces) total += f;
  return total;
}

TEST(FemGravity, TotalLoadIsGarmentMassTimesG) {
  for (const int degree : {1, 2}) {
    TubeCase tube("linear biot", EndCondition::free_ends, coarse);
    tube.problem.gravity_m_per_s2 = Vec3(0.3, -9.7, 0.2);
    FemParameters parameters;
    parameters.element_degree = degree;
    FemBackend backend(tube.problem, parameters);
    const Vec3 expected =
        tube.fabric.areal_density_kg_per_m2 * rest_area(tube.mesh) * tube.problem.gravity_m_per_s2;
    const Vec3 total = sum(backend.gravity_load_N());
    std::printf("degree %d: total load %.12e N, M g %.12e N\n", degree, total.norm(),
                expected.norm());
    // Round-off only: the quadrature integrates the shape functions exactly.
    EXPECT_LT((total - expected).norm(), 1e-12 * expected.norm()) << "degree " << degree;
  }
}

// Linear triangles: int N_k dA is a third of each triangle at each corner, the barycentric rest
// area the mass-spring backend lumps its masses on.
TEST(FemGravity, LinearTrianglesLoadTheLumpedMasses) {
  TubeCase tube("linear biot", EndCondition::free_ends, coarse);
  FemBackend backend(tube.problem, FemParameters{});
  const std::vector<Vec3> load = backend.gravity_load_N();
  const std::vector<double> area = rest_vertex_areas_m2(tube.mesh);
  ASSERT_EQ(load.size(), area.size());
  for (std::size_t v = 0; v < area.size(); ++v) {
    const Vec3 expected =
        tube.fabric.areal_density_kg_per_m2 * area[v] * tube.problem.gravity_m_per_s2;
    EXPECT_LT((load[v] - expected).norm(), 1e-12 * expected.norm()) << "vertex " << v;
  }
}

// Quadratic triangles: the corner functions integrate to zero over a flat triangle and each
// edge midpoint's to a third of the triangle's area, so the corners carry nothing and each
// midpoint a third of the weight of its one or two triangles.
TEST(FemGravity, QuadraticTrianglesLoadTheMidpointsOnly) {
  TubeCase tube("linear biot", EndCondition::free_ends, coarse);
  FemParameters parameters;
  parameters.element_degree = 2;
  FemBackend backend(tube.problem, parameters);
  const std::vector<Vec3> load = backend.gravity_load_N();
  const double weight_per_area =
      tube.fabric.areal_density_kg_per_m2 * tube.problem.gravity_m_per_s2.norm();
  const double total = weight_per_area * rest_area(tube.mesh);
  for (int v = 0; v < tube.mesh.n_vertices; ++v)
    EXPECT_LT(load[v].norm(), 1e-14 * total) << "corner " << v;
  // Each edge's area share from the triangles that hold it, keyed as the backend's midpoints
  // are ordered is not known here: compare the sorted shares instead.
  const std::vector<double> areas = rest_triangle_areas(tube.mesh);
  std::map<std::pair<int, int>, double> edge_share;
  for (std::size_t t = 0; t < tube.mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      int a = tube.mesh.triangles[t][k], b = tube.mesh.triangles[t][(k + 1) % 3];
      if (a > b) std::swap(a, b);
      edge_share[{a, b}] += areas[t] / 3.0;
    }
  std::vector<double> expected, measured;
  for (const auto& [edge, share] : edge_share) expected.push_back(weight_per_area * share);
  for (std::size_t k = tube.mesh.n_vertices; k < load.size(); ++k)
    measured.push_back(load[k].norm());
  ASSERT_EQ(measured.size(), expected.size());
  std::sort(expected.begin(), expected.end());
  std::sort(measured.begin(), measured.end());
  for (std::size_t e = 0; e < expected.size(); ++e)
    EXPECT_NEAR(measured[e], expected[e], 1e-12 * total) << "midpoint " << e;
}

// A tube on a horizontal cylinder under gravity: the membrane's internal forces sum to zero
// and the pin's reaction vanishes, so the body's contact forces carry the garment's weight.
TEST(FemGravity, ContactForcesCarryTheWeight) {
  for (const int degree : {1, 2}) {
    TubeCase tube("linear biot", EndCondition::free_ends, coarse);
    tube.problem.gravity_m_per_s2 = Vec3(0.0, -9.81, 0.0);  // across the axis (z)
    FemParameters parameters;
    parameters.element_degree = degree;
    FemBackend backend(tube.problem, parameters);
    const double alpha = 1.2;
    tube.grow_to(alpha);
    backend.set_positions(tube.placed(alpha * tube.rest_radius_m));
    const StepReport report = backend.solve({0, alpha, true});
    const Vec3 weight =
        tube.fabric.areal_density_kg_per_m2 * rest_area(tube.mesh) * tube.problem.gravity_m_per_s2;
    const Vec3 carried = sum(backend.state().contact_force_N);
    std::printf("degree %d: contact %.9e N, weight %.9e N, |sum| %.2e N; %s\n", degree, carried.y(),
                weight.y(), (carried + weight).norm(), report.text().c_str());
    // Degree 1: the contact forces are the nodal multipliers, in equilibrium to the Newton
    // tolerance (1e-10 Y h per node, measured |sum| 1.7e-13 N): far below 1e-8 of the weight.
    // Degree 2: the state's contact forces are the recovered traction times flat vertex areas
    // (fem_state.h), which carry the chord error of 12 vertices round, (pi/12)^2/6 = 1.1%;
    // measured 0.68%.
    const double tolerance = degree == 1 ? 1e-8 : 0.011;
    EXPECT_LT((carried + weight).norm(), tolerance * weight.norm()) << "degree " << degree;
  }
}

}  // namespace
}  // namespace tightfit
