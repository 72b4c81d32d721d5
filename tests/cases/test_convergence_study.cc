// A mesh-convergence study (cases/convergence_run.h) makes each level's scenario once and runs
// it on every backend in turn: garment T on the cylinder (cases/cylinder_T.prm at Mesh scale 2
// and 1, started on the cylinder at alpha 1.2, load steps to 1.4) on the mass-spring and the
// FE backend. The study makes two scenarios, not one per level and backend, and each backend's
// pressures at each level are those of an independent run on a scenario made afresh for it: to
// the last bit, since the second backend runs on a scenario the first left with the cylinder at
// alpha 1.4, and a run that did not start from the body's own starting shape would differ.
#include "cases/case_parameters.h"
#include "cases/convergence_run.h"
#include "cases/scenario.h"
#include "cases/scenario_run.h"
#include "cylinder_start.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace tightfit {
namespace {

constexpr double rest_radius_m = 2 * 0.157 / (2 * M_PI);  // R0 of garment T, alpha = r / R0

void read_garment_t(CaseFile& file) {
  file.read(TIGHTFIT_SOURCE_DIR "/cases/cylinder_T.prm",
            {"Garment/Mesh scale=2", "Protocol/Final alpha=1.4", "Protocol/Alpha increment=0.1",
             "Measurements/List=cylinder theory"});
  testing::start_cylinder_at(file, 1.2, rest_radius_m);
}

TEST(ConvergenceStudy, MakesEachLevelOnceAndMatchesIndependentRuns) {
  CaseFile file;
  read_garment_t(file);
  CaseParameters parameters = file.parameters();
  parameters.output.write_files = false;
  const std::vector<std::string> names{"massspring", "fem"};
  std::vector<NamedBackendFactory> backends;
  // The problem each backend was made on, per backend: the problem lives in its scenario, so
  // two runs handed the same one ran the same scenario.
  std::vector<std::vector<const Problem*>> problems(names.size());
  for (std::size_t b = 0; b < names.size(); ++b)
    backends.push_back({names[b], [&file, &problems, b, name = names[b]](const Problem& problem) {
                          problems[b].push_back(&problem);
                          return file.create_backend(name, problem);
                        }});

  ConvergenceSettings settings;
  settings.n_levels = 2;
  int headers = 0, level_0_vertices = 0;
  const Problem* level_0_problem = nullptr;
  settings.on_levels_made = [&](const Scenario& level_0) {
    ++headers;
    level_0_vertices = level_0.mesh.n_vertices;
    level_0_problem = &level_0.problem;
  };
  std::ostringstream log;
  const ConvergenceStudy study = run_convergence_study(parameters, settings, backends, "", log);
  ASSERT_TRUE(study.completed()) << log.str();

  // One scenario per level, shared by both backends; the hook sees level 0's once.
  EXPECT_EQ(study.scenarios_made, 2);
  EXPECT_EQ(headers, 1);
  ASSERT_EQ(study.backends.size(), 2u);
  EXPECT_EQ(level_0_vertices, study.backends[0].levels.at(0).n_vertices);
  // Both backends ran level 0 on the scenario the hook saw, and level 1 on one other scenario.
  for (const auto& made_on : problems) {
    ASSERT_EQ(made_on.size(), 2u);
    EXPECT_EQ(made_on[0], level_0_problem);
    EXPECT_NE(made_on[1], level_0_problem);
  }
  EXPECT_EQ(problems[0][1], problems[1][1]);

  for (std::size_t b = 0; b < names.size(); ++b) {
    const BackendConvergence& backend = study.backends[b];
    EXPECT_EQ(backend.backend, names[b]);
    ASSERT_EQ(backend.levels.size(), 2u);
    for (int level = 0; level < 2; ++level) {
      SCOPED_TRACE(names[b] + " level " + std::to_string(level));
      std::unique_ptr<Scenario> alone =
          make_scenario(convergence_level_parameters(parameters, level, settings.ratio));
      std::ostringstream alone_log;
      const RunResult expected = run_scenario(*alone, backends[b].create, "", alone_log);
      ASSERT_TRUE(expected.completed) << alone_log.str();
      const ConvergenceLevel& l = backend.levels[level];
      EXPECT_EQ(l.n_vertices, alone->mesh.n_vertices);
      ASSERT_EQ(l.run.steps.size(), expected.steps.size());
      ASSERT_EQ(expected.steps.size(), 3u);  // alpha 1.2 (settling), 1.3, 1.4
      for (std::size_t k = 0; k < expected.steps.size(); ++k) {
        const StepMeasurement& got = l.run.steps[k];
        const StepMeasurement& want = expected.steps[k];
        EXPECT_EQ(got.alpha, want.alpha);
        // Bit for bit: the same scenario, the same backend, the same order of operations.
        EXPECT_EQ(got.p_mean_Pa(), want.p_mean_Pa()) << "step " << k;
        EXPECT_EQ(got.summary.max_Pa, want.summary.max_Pa) << "step " << k;
        EXPECT_EQ(got.report.iterations, want.report.iterations) << "step " << k;
        EXPECT_GT(got.p_mean_Pa(), 0.0) << "step " << k << ": the tube presses on the cylinder";
      }
    }
  }
}

}  // namespace
}  // namespace tightfit
