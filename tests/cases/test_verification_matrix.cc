// The verification matrix: every material law x end condition x backend on
// the paper's garment T, coarse mesh, against the closed form (docs/model.md, "Closed forms") at
// alpha = 1.2, 1.5 and 1.8.
//
// Mesh: the case's own mesh (Mesh scale 1: 480 vertices, mean edge 17.3 mm), the coarse
// mesh of the paper's Figure 14; the whole matrix runs in about 10 s on one core.
//
// The errors are those of the convergence study of each combination (nu12 = 0.3):
//   tightfit convergence cases/cylinder_T.prm --levels 2 --set "Garment/Mesh scale=2"
//     --set "Protocol/Alpha increment=0.3" --set "Material/Law=LAW"
//     --set "Constraints/Held groups=GROUPS" --set "Material/Poisson ratio weft-warp=0.3"
// (GROUPS empty for free ends, "bottom, top" for held ones)
// (linear Biot free ends also with --levels 3). Error of the level this test runs (scale 1)
// at alpha 1.2 / 1.5 / 1.8, mass-spring | FEM, in %; every error is negative (the tube
// reads low: linear triangles inscribe a polygon in the circle):
//   linear Biot, free   -0.66 -0.37 -0.31 | -0.66 -0.37 -0.31   (3 levels to 8.8 mm: observed
//                       order 2.0 | 1.99, Richardson -0.02 | -0.007 at alpha 1.8)
//   linear Biot, held   -0.62 -0.31 -0.24 | -0.62 -0.31 -0.24
//   St V-K, free        -0.83 -0.60 -0.73 | -0.83 -0.59 -0.71
//   St V-K, held        -0.78 -0.48 -0.41 | -0.78 -0.48 -0.41
//   neo-Hookean, free   -0.58 -0.29 -0.22 | -0.58 -0.29 -0.22
//   neo-Hookean, held   -0.49 -0.21 -0.15 | -0.49 -0.21 -0.15
// From scale 2 to scale 1 every error falls about fourfold (linear triangles, error ~ h^2)
// and the Richardson extrapolation of the two levels lies within 0.13% of the closed form.
// Both backends hold the tube on the body with the same augmented-Lagrangian contact, so
// they solve the same discrete problem and read the same errors to 2.6e-4 (St V-K free ends
// at alpha 1.8: the mass-spring backend's bending springs and stop rule). Each case checks its
// own measured errors (the table below, from this test's printout): negative, and within 1e-4
// of the measured value. (With the plain penalty, Mass spring/Contact multiplier updates = 0,
// the tube sits p / k inside the body and the mass-spring St V-K free tube read -1.5% at alpha
// 1.8: d ln p / d ln alpha = 5.85 there magnifies the 0.13% shortfall in hoop stretch.)
#include "cases/case_parameters.h"
#include "cases/scenario.h"
#include "cases/scenario_run.h"
#include "cylinder_start.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace tightfit {
namespace {

struct MatrixCase {
  const char* law;
  const char* ends;
  const char* backend;
  // The relative error measured at alpha 1.2, 1.5, 1.8 (this test's printout): every one
  // negative, linear triangles inscribing a polygon in the circle.
  double measured_error[3];
};

std::string case_name(const ::testing::TestParamInfo<MatrixCase>& info) {
  std::string name = std::string(info.param.law) + "_" + info.param.ends + "_" + info.param.backend;
  for (char& c : name)
    if (c == ' ') c = '_';
  return name;
}

class VerificationMatrix : public ::testing::TestWithParam<MatrixCase> {};

TEST_P(VerificationMatrix, MeanPressureMatchesClosedForm) {
  const MatrixCase& c = GetParam();
  CaseFile file;
  // Garment T as in cases/cylinder_T.prm, on its own mesh (level 1 of the study above).
  for (const char* entry :
       {"Garment/Name=T", "Garment/Tube/Panel width=0.157", "Garment/Tube/Panel height=0.24",
        "Garment/Tube/Number of panels=2", "Garment/Edge length weft=0.008",
        "Garment/Edge length warp=0.022", "Garment/Mesh scale=1",
        // nu12 = 0.3 (nu21 = 0.16) makes free and held ends differ by up to 50% at alpha 1.8.
        "Material/Poisson ratio weft-warp=0.3", "Output/Write VTU=false"})
    file.set(entry);
  file.set(std::string("Material/Law=") + c.law);
  if (std::string(c.ends) == "held") file.set("Constraints/Held groups=bottom, top");
  // Start on a cylinder at alpha 1.2 and grow it to 1.5 and 1.8: the three alphas checked.
  const std::vector<double> alphas = {1.2, 1.5, 1.8};
  std::ostringstream log;
  const RunResult run =
      testing::run_on_cylinder(file, c.backend, alphas, 2 * 0.157 / (2 * M_PI), log);
  ASSERT_TRUE(run.completed) << run.failure << "\n" << log.str();
  ASSERT_EQ(run.steps.size(), alphas.size());
  for (std::size_t k = 0; k < run.steps.size(); ++k) {
    const StepMeasurement& m = run.steps[k];
    std::printf("%s, %s ends, %s: alpha %.1f  p %.2f Pa  closed form %.2f Pa  error %+.5f\n", c.law,
                c.ends, c.backend, m.alpha, m.p_mean_Pa(), m.p_theory_Pa, m.rel_error);
    EXPECT_EQ(m.summary.contact_fraction, 1.0) << "alpha " << m.alpha;
    // One-sided: the polygon reads low. Within 1e-4 of the measured value: the stop rule of
    // the mass-spring backend moves a mean by less (the two backends, one discrete problem,
    // differ by at most 2.6e-4), Newton's far less.
    EXPECT_LT(m.rel_error, 0.0) << "alpha " << m.alpha;
    EXPECT_NEAR(m.rel_error, c.measured_error[k], 1e-4) << "alpha " << m.alpha;
  }
}

INSTANTIATE_TEST_SUITE_P(
    AllLawsEndsBackends, VerificationMatrix,
    ::testing::Values(
        MatrixCase{"linear biot", "free", "massspring", {-0.00661, -0.00368, -0.00310}},
        MatrixCase{"linear biot", "free", "fem", {-0.00656, -0.00363, -0.00304}},
        MatrixCase{"linear biot", "held", "massspring", {-0.00621, -0.00308, -0.00232}},
        MatrixCase{"linear biot", "held", "fem", {-0.00617, -0.00308, -0.00231}},
        MatrixCase{"st venant kirchhoff", "free", "massspring", {-0.00829, -0.00592, -0.00727}},
        MatrixCase{"st venant kirchhoff", "free", "fem", {-0.00825, -0.00582, -0.00701}},
        MatrixCase{"st venant kirchhoff", "held", "massspring", {-0.00779, -0.00469, -0.00398}},
        MatrixCase{"st venant kirchhoff", "held", "fem", {-0.00774, -0.00472, -0.00400}},
        MatrixCase{"neo hookean", "free", "massspring", {-0.00582, -0.00293, -0.00213}},
        MatrixCase{"neo hookean", "free", "fem", {-0.00578, -0.00284, -0.00218}},
        MatrixCase{"neo hookean", "held", "massspring", {-0.00487, -0.00202, -0.00144}},
        MatrixCase{"neo hookean", "held", "fem", {-0.00486, -0.00204, -0.00146}}),
    case_name);

}  // namespace
}  // namespace tightfit
