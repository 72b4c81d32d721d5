// The FE backend on a graded mesh: each node's contact penalty and stop rule follow its own
// edge length h_k (fem/contact_nodes.h), so a tube whose two panels are meshed four times apart
// converges as a uniform tube does and reads the pressures the discrete balance predicts.
//
// On a graded ring the discrete equilibrium is not uniform: a seam vertex between chords of
// different angles balances them tangentially, so the coarse panel carries a higher hoop
// tension, in a ratio the seam's balance gives in closed form (below).
#include "cases/cylinder_theory.h"
#include "fem/fem_backend.h"
#include "tube_problem.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace tightfit {
namespace {

using testing::TubeCase;

const double kPanelWidth = 0.1878, kHeight = 0.24, kRowSpacing = 0.024;

// Two panels of 4 5T sewn into a ring, panel 1 with n_a cells round, panel 2 with n_b.
Garment graded_tube(int n_a, int n_b) {
  Garment garment;
  garment.name = "graded 4 5T";
  const int cells[2] = {n_a, n_b};
  for (int p = 0; p < 2; ++p) {
    Panel panel = make_rectangle_panel("panel " + std::to_string(p + 1), kPanelWidth, kHeight,
                                       MeshSpacing{kPanelWidth / cells[p], kRowSpacing});
    panel.layout_offset_m = Vec2(p * kPanelWidth, 0.0);
    garment.panels.push_back(std::move(panel));
    garment.seams.push_back({p, "right", (p + 1) % 2, "left"});
  }
  return garment;
}

struct Reading {
  double error = 0.0;  // mean pressure / closed form - 1
  double spread = 0.0;
  // Mean pressure over the vertices inside panel 1 (y > 0) and panel 2 (y < 0), seams left out.
  double p_panel_1_Pa = 0.0, p_panel_2_Pa = 0.0;
  int newton = 0;
  std::string detail;
};

Reading tube_at(int n_a, int n_b, double alpha) {
  TubeCase tube("linear biot", EndCondition::free_ends, graded_tube(n_a, n_b));
  FemBackend backend(tube.problem, FemParameters{});
  tube.grow_to(alpha);
  backend.set_positions(tube.placed(alpha * tube.rest_radius_m));
  const StepReport report = backend.solve({0, alpha, false});
  const SurfaceState state = backend.state();
  const PressureSummary p = tube.pressure(state);
  const PressureField field = extract_pressure(
      tube.mesh.triangles, state, VertexAreaDefinition::barycentric, tube.cylinder.get());
  double sum[2] = {0.0, 0.0};
  int count[2] = {0, 0};
  for (int w = 0; w < tube.mesh.n_vertices; ++w) {
    const double y = state.positions_m[w].y();
    if (std::abs(y) < 1e-3 * tube.rest_radius_m) continue;  // a seam
    sum[y < 0] += field.pressure_Pa[w];
    ++count[y < 0];
  }
  EXPECT_EQ(p.contact_fraction, 1.0);
  EXPECT_LE(backend.max_penetration_m(), 1e-9);
  const double theory = closed_form_pressure_Pa("linear biot", EndCondition::free_ends, tube.fabric,
                                                tube.rest_radius_m, alpha);
  return {p.mean_Pa / theory - 1, p.std_Pa / p.mean_Pa, sum[0] / count[0],
          sum[1] / count[1],      report.iterations,    report.text()};
}

TEST(FemGradedMesh, PanelsBalanceAtTheSeamAndTheMeanMatchesTheClosedForm) {
  const double alpha = 1.5;
  const int n_a = 36, n_b = 9;  // cells round each panel: elements four times apart in size
  const Reading graded = tube_at(n_a, n_b, alpha);
  const Reading uniform = tube_at(18, 18, alpha);
  // The tangential balance of a seam vertex between chords of angles theta_a and theta_b under
  // frictionless contact: T_a cos(theta_a / 2) = T_b cos(theta_b / 2). Inside a panel the
  // tension (so the pressure T / r) is uniform, so the panels' pressures stand in that ratio.
  const double seam_ratio = std::cos(M_PI / (2 * n_a)) / std::cos(M_PI / (2 * n_b));
  const double panel_ratio = graded.p_panel_2_Pa / graded.p_panel_1_Pa;
  std::printf(
      "graded %d/%d: error %+.4e, panels %.4f / %.4f Pa, ratio %.5f (seam balance %.5f), "
      "%d Newton | %s\n",
      n_a, n_b, graded.error, graded.p_panel_1_Pa, graded.p_panel_2_Pa, panel_ratio, seam_ratio,
      graded.newton, graded.detail.c_str());
  std::printf("uniform 18/18: error %+.4e, spread %.2e, %d Newton | %s\n", uniform.error,
              uniform.spread, uniform.newton, uniform.detail.c_str());
  // Measured: ratio - 1 is 1.026 times the seam balance's (the tension varies by 4e-4 inside a
  // panel, near the seams); within 10%.
  EXPECT_NEAR(panel_ratio - 1, seam_ratio - 1, 0.1 * (seam_ratio - 1));
  // The coarse panel's polygon error dominates: measured -1.309e-2 (its 9 sides per half ring
  // give (pi/18)^2 / 24 = 1.3e-3 of hoop stretch, about -0.9% of pressure with this law's
  // sensitivity at alpha 1.5, and the fine panel reads 1.4% below it), against -4.23e-3 for the
  // uniform 18/18 tube. Both below the closed form; each within 2% of its measured value.
  EXPECT_LT(graded.error, 0.0);
  EXPECT_NEAR(graded.error, -1.309e-2, 0.02 * 1.309e-2);
  EXPECT_LT(uniform.error, 0.0);
  EXPECT_NEAR(uniform.error, -4.232e-3, 0.02 * 4.232e-3);
  EXPECT_LE(uniform.spread, 1e-8);
}

}  // namespace
}  // namespace tightfit
