// Force balance of a dressed body, on both backends: the body carries the garment, so the
// contact forces on the garment add up to minus its weight (the fabric's mass, rho_A times its
// rest area, times g: mass is conserved, core/garment.h) with gravity, and to zero without it,
// however large each of them is.
//
// - Garment T on a horizontal cylinder (axis x, gravity along -z, free ends, nu12 0.2021),
//   settled at alpha 1.2 without gravity, then measured at alpha 1.5 with it: the contact forces
//   press with about 90 N in all and net to zero, then to the weight, 0.0783 N.
// - The sheet of cases/sheet_on_plane.prm lying on the plane under gravity: every vertex reads
//   the weight per area as contact traction (p_theory_Pa of the `weight on plane` measurement).
//
// Both are bounded by the stop rule: the FE backend stops at a residual of 1e-10 of its force
// scale per node, the mass-spring backend at 1e-4 of its tension scale Y h^2 / L per vertex
// (report.tolerance_N), and the contact forces balance the garment's own only to those
// residuals, so their sum misses by at most the vertices times the tolerance. Measured, relative
// to the weight (bounds: about twice the mass-spring figures, 1e-8 and 1e-9 for the FE ones):
//                         mass-spring   FE
//   tube, gravity off     1.1e-12 N     5.0e-13 N   (of 38.9 N pressing)
//   tube, gravity on      1.9e-4        2.8e-9
//   sheet, sum            6.6e-3        4.0e-13
//   sheet, worst vertex   6.6e-3        8.3e-12     (its traction against rho_A g)
// The mass-spring sheet stops settling while its residual is still of the order of a hundredth
// of its weight per vertex: the stop rule at the contact load (core/load_step.h) asks for 1e-4
// of the mean contact force on a vertex, but not below a tenth of the tension-scale rule,
// 3.39e-6 N here, 9.9e-3 of the mean weight on a vertex (3.43e-4 N): the sheet's bound, 1e-2.
#include "body_case.h"
#include "cases/case_parameters.h"
#include "cases/scenario.h"
#include "cases/scenario_run.h"
#include "cylinder_start.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

namespace tightfit {
namespace {

struct Tolerances {
  double tube, sheet;  // relative to the weight
};
Tolerances tolerances(const std::string& backend) {
  return backend == "fem" ? Tolerances{1e-8, 1e-9} : Tolerances{5e-4, 1e-2};
}

struct Balance {
  Vec3 contact_N = Vec3::Zero();  // sum of the contact forces on the garment
  double pressing_N = 0.0;        // sum of their magnitudes
  Vec3 weight_N = Vec3::Zero();   // the garment's weight, zero without gravity
  double bound_N = 0.0;           // the vertices times the stop rule's tolerance
};

Balance balance(const Scenario& scenario, const StepMeasurement& m, bool gravity_on) {
  Balance b;
  for (const Vec3& f : m.state.contact_force_N) {
    b.contact_N += f;
    b.pressing_N += f.norm();
  }
  if (gravity_on)
    b.weight_N = scenario.parameters.fabric.areal_density_kg_per_m2 * rest_area(scenario.mesh) *
                 scenario.problem.gravity_m_per_s2;
  b.bound_N = double(m.state.size()) * m.report.tolerance_N;
  return b;
}

class ForceBalance : public ::testing::TestWithParam<const char*> {};

TEST_P(ForceBalance, TubeOnHorizontalCylinderCarriesItsWeightAndNothingElse) {
  CaseFile file;
  for (const char* entry :
       {"Garment/Name=T", "Garment/Tube/Panel width=0.157", "Garment/Tube/Panel height=0.24",
        "Material/Law=linear biot", "Material/Poisson ratio weft-warp=0.2021",
        "Material/Areal density=0.1057", "Body/Cylinder/Axis=1,0,0", "Protocol/Up=0,0,1",
        "Protocol/Gravity while measuring=true", "Measurements/List=", "Output/Write VTU=false"})
    file.set(entry);
  const std::vector<double> alphas = {1.2, 1.5};
  std::ostringstream log;
  CaseParameters parameters = file.parameters();
  std::vector<StepMeasurement> steps;  // whole: the run keeps the last one's arrays only
  const RunResult run =
      testing::run_on_cylinder(file, GetParam(), alphas, 2 * 0.157 / (2 * M_PI), log,
                               [&](const StepMeasurement& m) { steps.push_back(m); });
  ASSERT_TRUE(run.completed) << run.failure << "\n" << log.str();
  ASSERT_EQ(steps.size(), 2u);
  parameters.output.write_files = false;
  const std::unique_ptr<Scenario> scenario = make_scenario(parameters);
  for (const StepMeasurement& m : steps) {
    const bool gravity_on = m.step == 1;
    const Balance b = balance(*scenario, m, gravity_on);
    const double miss_N = (b.contact_N + b.weight_N).norm();
    std::printf(
        "%s alpha %.1f, gravity %s: |sum of contact forces + weight| %.3e N; contact "
        "forces %.4f N in all, weight %.6f N, bound %.3e N\n",
        GetParam(), m.alpha, gravity_on ? "on" : "off", miss_N, b.pressing_N, b.weight_N.norm(),
        b.bound_N);
    EXPECT_LT(miss_N, b.bound_N) << "alpha " << m.alpha;
    if (gravity_on) {
      EXPECT_LT(miss_N, tolerances(GetParam()).tube * b.weight_N.norm());
    }
  }
}

TEST_P(ForceBalance, SheetOnPlaneCarriesItsWeightAtEveryVertex) {
  CaseFile file;
  file.read(std::string(TIGHTFIT_CASES_DIR) + "/sheet_on_plane.prm", {"Output/Write VTU=false"});
  const testing::CaseFileRun r = testing::run_case_file(file, GetParam());
  const RunResult& run = r.run;
  ASSERT_TRUE(run.completed) << run.failure << "\n" << r.log;
  const StepMeasurement& m = run.steps.back();
  const Balance b = balance(*r.scenario, m, true);
  const double miss_N = (b.contact_N + b.weight_N).norm();
  double worst = 0.0;
  for (double p : m.field.pressure_Pa) worst = std::max(worst, std::abs(p / m.p_theory_Pa - 1));
  std::printf(
      "%s sheet: |sum of contact forces + weight| %.3e N of %.6f N, bound %.3e N; "
      "pressure %.6f Pa, weight per area %.6f Pa, worst vertex %.2e\n",
      GetParam(), miss_N, b.weight_N.norm(), b.bound_N, m.p_mean_Pa(), m.p_theory_Pa, worst);
  EXPECT_LT(miss_N, b.bound_N);
  const double tolerance = tolerances(GetParam()).sheet;
  EXPECT_LT(miss_N, tolerance * b.weight_N.norm());
  EXPECT_LT(worst, tolerance);
}

INSTANTIATE_TEST_SUITE_P(Backends, ForceBalance, ::testing::Values("massspring", "fem"));

}  // namespace
}  // namespace tightfit
