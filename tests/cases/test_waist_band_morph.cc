// cases/waist_band_morph.prm, coarsened (a band of 90 vertices, the morph in two steps of 0.5):
// a band round the waist of MakeHuman's default female while she morphs into the default male,
// on the mass-spring backend with friction mu = 0.3. At every stable state:
// - no vertex lies deeper in the body than the gap tolerance (auto: 1e-8 m raised to the gap
//   the stop rule resolves on this mesh, docs/backends.md), measured by the body's own signed
//   distance of the state's positions;
// - the contact forces (normal and friction) add up to zero within the stop rule: nothing else
//   acts on the free band, and its own forces sum to zero (measured 1.2e-3 N at most, of 3.8 to
//   11.5 N of normal force; the bound is the stop rule's residual per vertex times the vertices,
//   4.3e-3 N);
// - the band presses (most of it in contact) with a pressure map that is finite and >= 0.
// And the mean pressure rises as the waist grows from 65.2 to 74.7 cm round (the band is 60).
// The band is placed from the female's landmarks (Centre = torso at waist, Radius = waist + 0.01).
#include "core/garment.h"
#include "core/load_step.h"
#include "tests/cases/body_case.h"

#include <cmath>
#include <vector>

namespace tightfit {
namespace {

TEST(WaistBandMorph, NoVertexDeeperThanTheToleranceAndForcesBalance) {
  const std::string bodies = TIGHTFIT_BODIES_DIR;
  CaseFile file;
  file.read(std::string(TIGHTFIT_CASES_DIR) + "/waist_band_morph.prm",
            {"Body/Mesh/File=" + bodies + "/makehuman_default_female_body_m.obj",
             "Body/Morph/Target mesh=" + bodies + "/makehuman_default_male_body_m.obj",
             "Protocol/Alpha increment=0.5", "Garment/Edge length weft=0.02",
             "Garment/Edge length warp=0.025"});
  std::vector<StepMeasurement> steps;  // whole: the run keeps the last one's arrays only
  const testing::CaseFileRun r = testing::run_case_file(
      file, "massspring", [&](const StepMeasurement& m) { steps.push_back(m); });
  const RunResult& run = r.run;
  ASSERT_TRUE(run.completed) << run.failure << "\n" << r.log;
  // The case leaves Solver/Gap tolerance at auto.
  StopRule rule;
  rule.gap_tolerance_auto = true;
  rule.raise_gap_tolerance_to_stop_rule(mean_rest_edge_length_m(r.scenario->mesh),
                                        rest_area(r.scenario->mesh));
  std::printf("gap tolerance %.3g m\n", rule.gap_tolerance_m);
  ASSERT_EQ(steps.size(), 3u);
  double previous_p = 0.0;
  for (const StepMeasurement& m : steps) {
    double deepest_m = 0.0;
    Vec3 total_N = Vec3::Zero();
    double normal_sum_N = 0.0;
    for (std::size_t v = 0; v < m.state.size(); ++v) {
      deepest_m = std::min(deepest_m, m.state.gap_m[v]);
      total_N += m.state.contact_force_N[v];
      normal_sum_N += m.field.normal_force_N[v];
      EXPECT_TRUE(std::isfinite(m.field.pressure_Pa[v]) && m.field.pressure_Pa[v] >= 0.0);
    }
    std::printf("alpha %.1f: p %.2f Pa, contact %.3f, deepest %.2e m, |sum f| %.2e N of %.3f N\n",
                m.alpha, m.p_mean_Pa(), m.summary.contact_fraction, -deepest_m, total_N.norm(),
                normal_sum_N);
    EXPECT_GE(deepest_m, -rule.gap_tolerance_m) << "alpha " << m.alpha;
    EXPECT_LT(total_N.norm(), double(m.state.size()) * m.report.tolerance_N) << "alpha " << m.alpha;
    EXPECT_GT(m.summary.contact_fraction, 0.5) << "alpha " << m.alpha;
    EXPECT_GT(m.p_mean_Pa(), previous_p) << "alpha " << m.alpha;
    previous_p = m.p_mean_Pa();
  }
}

}  // namespace
}  // namespace tightfit
