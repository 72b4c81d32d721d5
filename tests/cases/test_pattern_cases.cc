// Garments cut from pattern files on the cylinder. cases/patterns/tube_45T.prm, the paper's
// "4 5T" read from a GarmentCode file, gives cases/cylinder_45T.prm's pressures on both
// backends; a tube whose side seams are equal circular arcs (cases/patterns/
// curved_seam_tube.json: each panel 18.78 cm wide at every height, so the sewn tube is the same
// flat cylinder of rest circumference 37.56 cm) meets the closed form (docs/model.md, "Closed
// forms").
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

const std::string source_dir = TIGHTFIT_SOURCE_DIR;

// Runs `case_file` (with `overrides`) on `backend` at the given alphas, starting on the
// cylinder at the first (tight from the start, as the verification matrix does).
RunResult run_case(const std::string& case_file, const std::vector<std::string>& overrides,
                   const std::string& backend, const std::vector<double>& alphas,
                   double rest_radius_m) {
  CaseFile file;
  file.read(source_dir + "/" + case_file, {"Output/Write VTU=false"});
  for (const std::string& o : overrides) file.set(o);
  std::ostringstream log;
  RunResult run = testing::run_on_cylinder(file, backend, alphas, rest_radius_m, log);
  EXPECT_TRUE(run.completed) << run.failure << "\n" << log.str();
  return run;
}

const double rest_radius_45T_m = 2 * 0.1878 / (2 * M_PI);

class PatternTube : public ::testing::TestWithParam<const char*> {};

TEST_P(PatternTube, TubeFromPatternFileGivesTheTubeGarmentsPressures) {
  const std::vector<double> alphas = {1.2, 1.8};
  const RunResult tube =
      run_case("cases/cylinder_45T.prm", {}, GetParam(), alphas, rest_radius_45T_m);
  const RunResult pattern =
      run_case("cases/patterns/tube_45T.prm",
               {"Garment/Pattern file/File=" + source_dir + "/cases/patterns/tube_45T.json"},
               GetParam(), alphas, rest_radius_45T_m);
  ASSERT_EQ(tube.steps.size(), alphas.size());
  ASSERT_EQ(pattern.steps.size(), alphas.size());
  for (std::size_t k = 0; k < alphas.size(); ++k) {
    const double p_tube = tube.steps[k].p_mean_Pa(), p_pattern = pattern.steps[k].p_mean_Pa();
    std::printf("%s alpha %.1f: tube %.9g Pa, pattern file %.9g Pa\n", GetParam(), alphas[k],
                p_tube, p_pattern);
    EXPECT_LT(std::abs(p_pattern - p_tube), 1e-6 * p_tube);
    EXPECT_EQ(pattern.steps[k].summary.contact_fraction, tube.steps[k].summary.contact_fraction);
  }
}

TEST_P(PatternTube, CurvedSeamTubeMeetsTheClosedForm) {
  const std::vector<double> alphas = {1.2, 1.8};
  const RunResult run =
      run_case("cases/patterns/tube_45T.prm",
               {"Garment/Pattern file/File=" + source_dir + "/cases/patterns/curved_seam_tube.json",
                "Garment/Pattern file/Mesh edge length=0.016"},
               GetParam(), alphas, rest_radius_45T_m);
  ASSERT_EQ(run.steps.size(), alphas.size());
  for (const StepMeasurement& m : run.steps) {
    std::printf("%s curved seams alpha %.1f: p %.4f Pa, closed form %.4f Pa, error %+.3f%%\n",
                GetParam(), m.alpha, m.p_mean_Pa(), m.p_theory_Pa, 100 * m.rel_error);
    EXPECT_EQ(m.summary.contact_fraction, 1.0);
    // Delaunay triangles of at most 16 mm (mean side 11 mm; 8 mm would take the mass-spring
    // backend minutes): measured +0.29 / +0.74 % (mass spring) and +0.25 / +0.73 % (FEM) at
    // alpha 1.2 / 1.8; 1 % leaves a third for the stop rules without hiding a real change.
    EXPECT_LT(std::abs(m.rel_error), 0.01);
  }
}

INSTANTIATE_TEST_SUITE_P(BothBackends, PatternTube, ::testing::Values("massspring", "fem"));

}  // namespace
}  // namespace tightfit
