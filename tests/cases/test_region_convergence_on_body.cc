// Mesh convergence by region on a mesh body (cases/convergence_run.h, cases/region_convergence.h):
// what the stocking's study does (docs/validation.md, "Mesh convergence on a body"), on a body
// whose answer is known. Garment T, held along the axis, on a 48-sided prism of circumradius
// rho = 1.5 R0 read from an OBJ with the smooth contact surface (within micrometres of the
// cylinder: test_tube_on_mesh_cylinder.cc), at three levels (Mesh scale 2, 1, 0.5) on the
// mass-spring backend, with two named regions, slabs across the tube's lower and upper halves.
// The edges divide the panel's width (15.7 cm) into 10, 20 and 40 and its height (6.6 cm) into
// 2, 4 and 8, so that each level's hoop has exactly twice the vertices of the one before and
// the mean edge halves exactly (with a ratio that only nearly halves, the hoop's N and the
// mean edge's ratio differ, and the observed order with them).
//
// The pressure is uniform along the tube, so each band's mean is the tube's: the closed form
// (nu = 0, Eq. 7) less the hoop polygon's shortfall, which linear triangles leave of order h^2
// ((pi / N)^2 / 6 of the strain, N the vertices round the hoop; docs/validation.md, "Mesh
// convergence" measures the order 1.96 to 1.98 on the analytic cylinder). So each region must
// show an observed order near 2 and a Richardson estimate closer to the closed form than its
// finest level.
#include "cases/case_parameters.h"
#include "cases/convergence_run.h"
#include "cases/cylinder_theory.h"
#include "tests/bodies/body_mesh_files.h"
#include "tests/cases/body_case.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace tightfit {
namespace {

using testing::setting;

constexpr double kPanelWidth = 0.157;  // garment T: R0 = 2 x 0.157 / (2 pi) = 4.997 cm
constexpr double kRestRadius = 2 * kPanelWidth / (2 * M_PI);
constexpr double kAlpha = 1.5;
constexpr int kFaces = 48;

TEST(RegionConvergenceOnBody, HeldTubeOnMeshCylinderConvergesAtSecondOrderToTheClosedForm) {
  const double rho = kAlpha * kRestRadius;
  // The prism: rings every 1 cm over 30 cm, so that the vertex normals under the tube are radial
  // (test_tube_on_mesh_cylinder.cc, write_prism).
  std::vector<double> z, radius;
  for (int k = 0; k <= 30; ++k) z.push_back(-0.15 + 0.01 * k), radius.push_back(rho);
  const std::string obj = testing::temporary_path("region_convergence_prism.obj");
  testing::write_obj(obj, testing::revolution_surface(z, radius, kFaces));

  CaseFile file;
  for (const std::string& s : std::vector<std::string>{
           "Garment/Name=T", setting("Garment/Tube/Panel width", kPanelWidth),
           "Garment/Tube/Panel height=0.066", "Garment/Edge length weft=0.00785",
           "Garment/Edge length warp=0.0165", "Garment/Mesh scale=2", "Material/Law=linear biot",
           "Material/Poisson ratio weft-warp=0", "Body/Kind=mesh", "Body/Mesh/File=" + obj,
           "Body/Mesh/Up axis=+z", "Placement/Kind=tube round axis",
           "Placement/Tube round axis/Axis=0,0,1",
           setting("Placement/Tube round axis/Radius", 1.005 * rho), "Protocol/Final alpha=1",
           "Constraints/Held groups=all", "Constraints/Held direction=0,0,1",
           "Solver/Relative tolerance=1e-4", "Solver/Stop norm=largest",
           "Solver/Gap tolerance=1e-8", "Output/Write VTU=false", "Measurements/List=regions",
           // The tube spans z -0.033 to 0.033 m (the placement centres it on the origin).
           "Measurements/Regions/Definitions=lower: slab z -1 0; upper: slab z 0 1"})
    file.set(s);
  CaseParameters parameters = file.parameters();
  parameters.output.write_files = false;
  std::vector<NamedBackendFactory> backends{{"massspring", [&file](const Problem& problem) {
                                               return file.create_backend("massspring", problem);
                                             }}};
  ConvergenceSettings settings;  // three levels, the edges halved each time
  std::ostringstream log;
  const ConvergenceStudy study = run_convergence_study(parameters, settings, backends, "", log);
  ASSERT_TRUE(study.completed()) << log.str();
  ASSERT_EQ(study.regions, (std::vector<std::string>{"lower", "upper"}));

  const double p_exact = closed_form_pressure_Pa("linear biot", EndCondition::held_ends,
                                                 parameters.fabric, kRestRadius, kAlpha);
  ASSERT_EQ(study.region_summary.size(), 2u);
  for (const RegionConvergenceRow& row : study.region_summary) {
    const RegionConvergence& r = row.estimate;
    SCOPED_TRACE(r.region);
    ASSERT_EQ(r.n_levels, 3);
    const double error_fine = (r.mean_fine_Pa - p_exact) / p_exact;
    const double error_richardson = (r.mean.extrapolated - p_exact) / p_exact;
    std::printf(
        "%s: finest %.3f Pa (%+.4f%%), order %.3f, Richardson %.3f Pa "
        "(%+.4f%%), GCI %.4f%%, closed form %.3f Pa\n",
        r.region.c_str(), r.mean_fine_Pa, 100 * error_fine, r.mean.order, r.mean.extrapolated,
        100 * error_richardson, 100 * r.mean.gci_fine, p_exact);
    ASSERT_TRUE(r.mean.order_observed);
    // The finest level reads low by the inscribed hoop's shortfall, (pi / N)^2 / 6 of the strain
    // alpha - 1, so alpha / (alpha - 1) times that of the pressure (Eq. 7), N = 80 round:
    // 7.71e-4 predicted, 7.74e-4 measured; bound 5% of the prediction (the rest is the smooth
    // surface's micrometres and the stop rule).
    const double n_round = 80, predicted = std::pow(M_PI / n_round, 2) / 6 * kAlpha / (kAlpha - 1);
    EXPECT_NEAR(error_fine, -predicted, 0.05 * predicted);
    // Observed order: measured 2.054; linear triangles' 2 within 0.15, about three times that.
    EXPECT_NEAR(r.mean.order, 2.0, 0.15);
    // Richardson removes the shortfall: measured 1.1e-5 from the closed form; bound 1e-4, the
    // stop rule's share (Solver/Relative tolerance) and 13 times below the finest level's error.
    EXPECT_LT(std::abs(error_richardson), 1e-4);
    // And the GCI covers the finest level's distance from the closed form, as it claims to
    // (measured 9.8e-4 against 7.7e-4).
    EXPECT_LT(std::abs(error_fine), r.mean.gci_fine);
  }
}

}  // namespace
}  // namespace tightfit
