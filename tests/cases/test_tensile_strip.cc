// A uniaxial strip test, simulated on each backend, reproduces the tensile curves it was given
// (Table 2's points, the numbers the tensile-curves law was built from): a strip of the
// paper's fabric is stretched to a measured strain between two grips that hold its ends along
// the pull and leave them free across it, and the grip's reaction per unit rest width is the
// measured force. The strip is kept flat (every vertex held along z) and one corner is held
// across the pull against rigid motion; nothing else touches it.
#include "bodies/plane.h"
#include "cases/case_parameters.h"
#include "core/constrained_directions.h"
#include "core/garment.h"
#include "core/rectangle_panel.h"
#include "core/tensile_curves.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numeric>

namespace tightfit {
namespace {

struct StripCase {
  const char* backend;
  bool along_weft;  // the pull along the weft (course) or the warp (wale)
  double strain;    // a Table 2 point
  double force_N_per_m;
};

class TensileStrip : public ::testing::TestWithParam<StripCase> {};

TEST_P(TensileStrip, GripForceIsTheMeasuredForce) {
  const StripCase& c = GetParam();
  // A strip 10 cm long and 2 cm wide, pulled along x (weft) or y (warp).
  const double length = 0.10, width = 0.02;
  const double width_x = c.along_weft ? length : width, width_y = c.along_weft ? width : length;
  Garment garment;
  garment.panels.push_back(
      make_rectangle_panel("strip", width_x, width_y, MeshSpacing{0.005, 0.005}));
  const SimulationMesh mesh = weld(garment);
  FabricParameters fabric;  // Table 2's curves by default
  const auto law = make_material_law("tensile curves", fabric);
  const Plane far_floor(Vec3(0, 0, -1), Vec3::UnitZ());

  Problem problem;
  problem.mesh = &mesh;
  problem.law = law.get();
  problem.fabric = &fabric;
  problem.body = &far_floor;
  const Vec3 pull = c.along_weft ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 across = c.along_weft ? Vec3::UnitY() : Vec3::UnitX();
  const std::string grip_a = c.along_weft ? "left" : "bottom";
  const std::string grip_b = c.along_weft ? "right" : "top";
  problem.constraints.push_back(held_along(mesh, grip_a, pull));
  problem.constraints.push_back(held_along(mesh, grip_b, pull));
  VertexConstraint flat;
  flat.group = "every vertex";
  flat.vertices.resize(mesh.n_vertices);
  std::iota(flat.vertices.begin(), flat.vertices.end(), 0);
  flat.direction = Vec3::UnitZ();
  problem.constraints.push_back(flat);
  VertexConstraint corner;
  corner.group = "one corner";
  corner.vertices = {mesh.vertex_groups.at(grip_a).front()};
  corner.direction = across;
  problem.constraints.push_back(corner);

  // Start stretched uniformly along the pull, at rest width across it.
  std::vector<Vec3> start(mesh.n_vertices);
  for (int u = 0; u < mesh.n_unwelded_vertices(); ++u) {
    const Vec2 X = mesh.layout_positions_m[u];
    Vec3 x(X.x(), X.y(), 0.0);
    x += c.strain * x.dot(pull) * pull;
    start[mesh.welded_index[u]] = x;
  }
  CaseFile file;
  const auto backend = file.create_backend(c.backend, problem);
  backend->set_positions(start);
  LoadStep step;
  backend->solve(step);  // throws a SolverError if it does not settle
  const SurfaceState state = backend->state();

  // The grip's reaction balances the garment's pull on the grip's vertices.
  double grip_force_N = 0.0;
  for (int v : mesh.vertex_groups.at(grip_b)) grip_force_N -= state.internal_force_N[v].dot(pull);
  const double tension = grip_force_N / width;
  // The strip's width at its middle, against the free strip's contraction 1 - g(e) for a weft
  // pull (the Poisson curve the law was given).
  double low = 1e9, high = -1e9;
  for (const Vec3& x : state.positions_m) {
    low = std::min(low, x.dot(across));
    high = std::max(high, x.dot(across));
  }
  std::printf("%s, %s strip at strain %.3f: %.4f N/m (measured %.4f), width stretch %.5f\n",
              c.backend, c.along_weft ? "weft" : "warp", c.strain, tension, c.force_N_per_m,
              (high - low) / width);
  // Linear triangles represent the uniform strip exactly; measured relative errors: FEM below
  // 1e-6, mass-spring up to 2.5e-5 (its stop rule's residual). Tolerance 1e-4 relative.
  EXPECT_NEAR(tension, c.force_N_per_m, 1e-4 * c.force_N_per_m);
  if (c.along_weft) {
    // Measured width errors: FEM below 1e-5; mass-spring 4.0e-3 at strain 0.35 and 2.8e-3 at
    // 0.60 (it stops on the residual force, and a free strip's width is its softest mode:
    // the force above is already right to 5e-5). Tolerances 1e-4 and 6e-3.
    const double tolerance = std::string(c.backend) == "fem" ? 1e-4 : 6e-3;
    const TensileCurves curves(fabric.tensile_curves());
    EXPECT_NEAR((high - low) / width, 1.0 - curves.lateral_contraction(c.strain), tolerance);
  }
}

INSTANTIATE_TEST_SUITE_P(Table2, TensileStrip,
                         ::testing::Values(StripCase{"massspring", true, 0.35, 24.5},
                                           StripCase{"fem", true, 0.35, 24.5},
                                           StripCase{"massspring", true, 0.60, 49.0},
                                           StripCase{"fem", true, 0.60, 49.0},
                                           StripCase{"massspring", false, 0.575, 24.5},
                                           StripCase{"fem", false, 0.575, 24.5},
                                           StripCase{"massspring", false, 0.825, 49.0},
                                           StripCase{"fem", false, 0.825, 49.0}),
                         [](const auto& info) {
                           char name[64];
                           std::snprintf(name, sizeof name, "%s_%s_%03d", info.param.backend,
                                         info.param.along_weft ? "weft" : "warp",
                                         static_cast<int>(std::lround(1000 * info.param.strain)));
                           return std::string(name);
                         });

}  // namespace
}  // namespace tightfit
