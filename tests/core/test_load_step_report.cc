// What both backends write alike of a load step (core/load_step_report.h): the stop threshold
// against its closed form, the header and clocks, and the failure message's parts.
#include "core/load_step_report.h"

#include "core/tension_scale.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tightfit {
namespace {

TEST(LoadStepReport, RelativeThresholdIsToleranceTimesTensionScale) {
  // Y h^2 / L with Y = 130 N/m, h = 0.01 m, L^2 = 0.09 m^2 (L = 0.3 m): 130e-4 / 0.3 N.
  StopRule rule;
  rule.relative_tolerance = 2e-4;
  const double scale_N = tension_scale_N(0.01, 0.09, 130.0);
  EXPECT_NEAR(scale_N, 130.0 * 1e-4 / 0.3, 1e-15);  // rounding of three operations
  EXPECT_DOUBLE_EQ(relative_threshold_N(rule, scale_N), 2e-4 * 130.0 * 1e-4 / 0.3);
}

TEST(LoadStepReport, HeaderAndClocks) {
  StepReport report;
  const StepClock clock;
  // Work the CPU for a moment so both clocks move.
  double sum = 0.0;
  for (int i = 1; i < 2000000; ++i) sum += std::sqrt(double(i));
  write_step_header("fem", LoadStep{4, 1.25, false}, 3e-6, StopNorm::rms, report);
  clock.read(report);
  EXPECT_EQ(report.backend, "fem");
  EXPECT_EQ(report.step_index, 4);
  EXPECT_EQ(report.alpha, 1.25);
  EXPECT_EQ(report.tolerance_N, 3e-6);
  EXPECT_EQ(report.stop_norm, StopNorm::rms);
  EXPECT_GT(sum, 0.0);
  EXPECT_GT(report.wall_seconds, 0.0);
  EXPECT_GE(report.cpu_seconds, 0.0);
}

TEST(LoadStepReport, FailureNamesTheStepTheResidualAndTheRounds) {
  StepReport report;
  report.largest_penetration_m = 2.5e-6;
  report.multiplier_updates = 3;
  report.rounds.resize(3);
  const std::string what = gap_not_closed_text(report, 1e-8);
  EXPECT_NE(what.find("largest penetration 2.5e-06 m"), std::string::npos) << what;
  EXPECT_NE(what.find("Gap tolerance 1e-08 m"), std::string::npos) << what;
  EXPECT_NE(what.find("after 3 contact multiplier updates"), std::string::npos) << what;
  EXPECT_NE(what.find(text(report.rounds)), std::string::npos) << what;

  const SolverError error = load_step_failure(StopReason::gap_not_closed, "mass spring",
                                              LoadStep{7, 1.8, false}, what, 4e-5, 2e-5, "more");
  EXPECT_EQ(error.reason(), StopReason::gap_not_closed);
  // The same as fields, for code and tests that must not read the message.
  EXPECT_EQ(error.failure().backend, "mass spring");
  EXPECT_EQ(error.failure().step_index, 7);
  EXPECT_EQ(error.failure().alpha, 1.8);
  EXPECT_EQ(error.failure().residual_N, 4e-5);
  EXPECT_EQ(error.failure().tolerance_N, 2e-5);
  // Copied (as a catch by value does), the fields stay; an error not from a step has none.
  const SolverError copy = error;
  EXPECT_EQ(copy.failure().step_index, 7);
  EXPECT_EQ(SolverError(StopReason::passed_into_body, "dressing").failure().step_index, -1);
  const std::string message = error.what();
  EXPECT_EQ(message.find("mass spring, load step 7 (alpha 1.8): " + what), 0u) << message;
  EXPECT_NE(message.find("; residual 4e-05 N (tolerance 2e-05 N); more"), std::string::npos)
      << message;
}

}  // namespace
}  // namespace tightfit
