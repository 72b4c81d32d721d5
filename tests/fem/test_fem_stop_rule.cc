// The FE backend's relative stop rule ('Finite elements/Relative tolerance', 'Stop norm'): its
// threshold is the mass-spring backend's, e Y h^2 / L (core/garment.h), computed here from the
// mesh; the state it accepts meets that threshold and, as the rule promises, lies within about
// e of strain of the exact equilibrium: its pressure against the one of the tight rule (1e-10
// Y h) and against the closed form p = T / r. A failed step names where its residual sits and
// the history of its iterations.
#include "cases/cylinder_theory.h"
#include "core/mesh_geometry.h"
#include "fem/fem_backend.h"
#include "tube_problem.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace tightfit {
namespace {

using testing::TubeCase;

const double kAlpha = 1.3;
const double kRelativeTolerance = 1e-4;

struct Settled {
  StepReport report;
  double p_mean_Pa = 0.0;
};

// The "4 5T" tube round the cylinder at alpha 1.3, held at its ends along the axis, started
// 3 % outside its radius so that Newton's method travels to the equilibrium (the contact
// rounds too).
Settled settle(const FemParameters& parameters) {
  TubeCase tube("linear biot", EndCondition::held_ends, MeshSpacing{0.02, 0.04});
  FemBackend backend(tube.problem, parameters);
  tube.grow_to(kAlpha);
  backend.set_positions(tube.placed(1.03 * kAlpha * tube.rest_radius_m));
  Settled s;
  s.report = backend.solve({0, kAlpha, false});
  s.p_mean_Pa = tube.pressure(backend.state()).mean_Pa;
  return s;
}

TEST(FemStopRule, TensionScaleRuleMeetsTheMassSpringThresholdAndTheClosedForm) {
  TubeCase tube("linear biot", EndCondition::held_ends, MeshSpacing{0.02, 0.04});
  const double h = mean_rest_edge_length_m(tube.mesh);
  const double expected_tolerance_N =
      kRelativeTolerance * tube.law->stiffness_scale() * h * h / std::sqrt(rest_area(tube.mesh));
  const double theory = closed_form_pressure_Pa("linear biot", EndCondition::held_ends, tube.fabric,
                                                tube.rest_radius_m, kAlpha);

  const Settled tight = settle(FemParameters{});
  std::printf("tight rule: p %.8f Pa (closed form %.8f), %d iterations, %s\n", tight.p_mean_Pa,
              theory, tight.report.iterations, tight.report.detail.c_str());
  for (const bool rms : {false, true}) {
    FemParameters parameters;
    parameters.relative_tolerance = kRelativeTolerance;
    parameters.stop_on_rms = rms;
    const Settled loose = settle(parameters);
    const char* norm = rms ? "rms" : "largest";
    std::printf(
        "%s: tolerance %.4e N (expected %.4e), residual %.3e N, p %.8f Pa (%+.2e from the "
        "tight rule's), %d iterations, %s\n",
        norm, loose.report.tolerance_N, expected_tolerance_N, loose.report.residual_N,
        loose.p_mean_Pa, loose.p_mean_Pa / tight.p_mean_Pa - 1, loose.report.iterations,
        loose.report.detail.c_str());
    EXPECT_NEAR(loose.report.tolerance_N, expected_tolerance_N, 1e-12 * expected_tolerance_N)
        << norm;
    EXPECT_LE(loose.report.residual_N, loose.report.tolerance_N) << norm;
    EXPECT_LE(loose.report.iterations, tight.report.iterations) << norm;
    // The pressure follows the hoop strain: a strain error of e = 1e-4 moves it by about
    // e / (alpha - 1) = 3e-4 of itself.
    EXPECT_LT(std::abs(loose.p_mean_Pa / tight.p_mean_Pa - 1), 3e-4) << norm;
  }
  // The discretisation's own error against p = T / r (the inscribed polygon of 20 vertices
  // round; measured 2.2 %).
  EXPECT_LT(std::abs(tight.p_mean_Pa / theory - 1), 3e-2);
}

// The message of a step that runs out of iterations: where the largest residual sits and the
// residual's history.
TEST(FemStopRule, FailedStepNamesWhereTheResidualSits) {
  TubeCase tube("linear biot", EndCondition::held_ends, MeshSpacing{0.03, 0.06});
  FemParameters parameters;
  parameters.max_newton_iterations = 2;
  FemBackend backend(tube.problem, parameters);
  tube.grow_to(1.8);
  backend.set_positions(tube.placed(tube.rest_radius_m));
  try {
    backend.solve({3, 1.8, false});
    FAIL() << "expected a SolverError";
  } catch (const SolverError& e) {
    const std::string what = e.what();
    std::printf("%s\n", what.c_str());
    EXPECT_NE(what.find("load step 3"), std::string::npos) << what;
    EXPECT_NE(what.find("largest residual"), std::string::npos) << what;
    EXPECT_NE(what.find("residual history"), std::string::npos) << what;
    // The residuals at iterations 0, 1 and 2, in the window being filled.
    EXPECT_NE(what.find("(3 Newton iterations)"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace tightfit
