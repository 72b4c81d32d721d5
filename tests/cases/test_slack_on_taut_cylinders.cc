// The tension field (Finite elements/Slack treatment, docs/model.md "Slack: the tension
// field") leaves a garment that is nowhere compressed as it was: the paper's cylinder cases on
// the FE backend, every load step, with and without it. "4 5T" starts slack (its rest radius is
// outside the body), so its first steps go through the relaxed law's slack regime.
#include "body_case.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace tightfit {
namespace {

class SlackOnTautCylinder : public ::testing::TestWithParam<const char*> {};

TEST_P(SlackOnTautCylinder, PressureIsUnchangedAtEveryStep) {
  CaseFile file;
  file.read(std::string(TIGHTFIT_CASES_DIR "/") + GetParam() + ".prm",
            {"Output/Write VTU=false", "Measurements/List="});
  const testing::CaseFileRun plain = testing::run_case_file(file, "fem");
  file.set("Finite elements/Slack treatment=tension field");
  const testing::CaseFileRun relaxed = testing::run_case_file(file, "fem");
  ASSERT_TRUE(plain.run.completed) << plain.run.failure;
  ASSERT_TRUE(relaxed.run.completed) << relaxed.run.failure;
  ASSERT_EQ(plain.run.steps.size(), relaxed.run.steps.size());
  double worst = 0.0;
  for (std::size_t s = 0; s < plain.run.steps.size(); ++s) {
    const double p = plain.run.steps[s].p_mean_Pa(), q = relaxed.run.steps[s].p_mean_Pa();
    if (p == 0.0) {
      EXPECT_EQ(q, 0.0) << "step " << s;  // "4 5T" before it touches
      continue;
    }
    worst = std::max(worst, std::abs(q / p - 1.0));
  }
  std::printf("%s: largest relative difference of the mean pressure %.2e\n", GetParam(), worst);
  // Measured 4.6e-10 (T) and 1.2e-10 (4 5T) here, up to 8.7e-10 from the command line with
  // every measurement on: the two runs take different Newton paths (the
  // relaxed law's slack regime) and each stops at its own 1e-10 residual; 3e-9 leaves the margin.
  EXPECT_LT(worst, 3e-9);
}

INSTANTIATE_TEST_SUITE_P(PaperCylinders, SlackOnTautCylinder,
                         ::testing::Values("cylinder_T", "cylinder_45T"));

}  // namespace
}  // namespace tightfit
