// The two backends on the same mesh of the paper's garment 4 5T (cases/cylinder_45T.prm, its
// defaults, the `tightfit compare` run): each is the other's outside reference. The FE
// backend's own rule (Finite elements/Residual tolerance 1e-10 Y h) leaves it exact to 1e-9;
// the mass-spring settle stops at the shared rule, which at the first contact steps is the one
// measured against the contact load (core/load_step.h, StopRule::threshold_N;
// docs/backends.md, "The stop rule at the contact load"): it bounds the pressure error by
// Solver/Contact load tolerance = 1e-4 of the pressure. Measured: within 7.4e-5 at every loaded
// step (3.1e-5 at alpha 1.05, where the tension-scale rule alone left 3.3e-4).
#include "cases/case_parameters.h"
#include "cases/comparison_run.h"
#include "cases/scenario.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

namespace tightfit {
namespace {

TEST(CylinderBackendsAgree, WithinOneTenThousandthAtEveryLoadedStep) {
  const std::filesystem::path out =
      std::filesystem::temp_directory_path() / "tightfit_cylinder_backends_agree";
  std::filesystem::remove_all(out);
  CaseFile file;
  file.read(TIGHTFIT_CASES_DIR "/cylinder_45T.prm",
            {"Output/Write VTU=false", "Measurements/List=cylinder theory"});
  std::unique_ptr<Scenario> scenario = make_scenario(file.parameters());
  const auto factory = [&file](const std::string& name) -> BackendFactory {
    return [&file, name](const Problem& problem) { return file.create_backend(name, problem); };
  };
  std::ostringstream log;
  const ComparisonResult result = run_comparison(*scenario, "massspring", factory("massspring"),
                                                 "fem", factory("fem"), out.string(), log);
  ASSERT_TRUE(result.completed()) << result.first.failure << result.second.failure << log.str();
  ASSERT_EQ(result.first.steps.size(), result.second.steps.size());
  int loaded = 0;
  for (std::size_t i = 0; i < result.first.steps.size(); ++i) {
    const StepMeasurement& ms = result.first.steps[i];
    const StepMeasurement& fe = result.second.steps[i];
    if (!(fe.p_mean_Pa() > 0)) continue;  // the tube hangs loose up to alpha 1
    ++loaded;
    const double difference = (fe.p_mean_Pa() - ms.p_mean_Pa()) / ms.p_mean_Pa();
    std::printf("alpha %.3f  mass spring %.4f Pa  FE %.4f Pa  %+.2e  (mass spring: %s)\n", ms.alpha,
                ms.p_mean_Pa(), fe.p_mean_Pa(), difference, ms.report.text().c_str());
    // The target, 1e-4; measured 7.4e-5 at most (the header).
    EXPECT_LT(std::abs(difference), 1e-4) << "alpha " << ms.alpha;
    // The mass-spring step stopped below the rule at its own contact load.
    EXPECT_LE(ms.report.load_tolerance_N, ms.report.tolerance_N) << "alpha " << ms.alpha;
    EXPECT_LT(ms.report.residual_N, ms.report.load_tolerance_N) << "alpha " << ms.alpha;
  }
  // Alpha 1.05 to 1.8 in steps of 0.05.
  EXPECT_EQ(loaded, 16);
  // At the first contact step the load rule is the tighter: c F = 1.7e-6 N against the
  // tension-scale rule's 1.35e-5 N (tests/core/test_contact_load_rule.cc).
  const StepReport& first_contact = result.first.steps.at(5).report;
  EXPECT_NEAR(first_contact.alpha, 1.05, 1e-12);
  EXPECT_LT(first_contact.load_tolerance_N, 0.2 * first_contact.tolerance_N);
  std::filesystem::remove_all(out);
}

}  // namespace
}  // namespace tightfit
