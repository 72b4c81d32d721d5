// Solver/Threads: body cases run with the body queries on one thread and on two give the same
// garment to the last bit (docs/performance-bodies.md, "Threads"), because each vertex's query
// writes only that vertex's state and every sum runs in vertex order. Three paths: the coarse
// stocking (the frame's carried contact, the inexact rounds, the regions written), a tube held
// by friction on a smooth mesh cylinder under gravity (friction's anchors at every stage and at
// the step's commit), and the bodice's dressing on the female (the open-seam garment's queries).
#include "cases/case_parameters.h"
#include "cases/scenario.h"
#include "cases/scenario_run.h"
#include "csv_rows.h"
#include "tests/bodies/body_mesh_files.h"
#include "tests/cases/body_case.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace tightfit {
namespace {

const std::string source_dir = TIGHTFIT_SOURCE_DIR;

std::string file_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// How many of the positions differ from `b`'s in any bit.
int differing(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  if (a.size() != b.size()) return int(std::max(a.size(), b.size()));
  int count = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    count += std::memcmp(a[i].data(), b[i].data(), sizeof(double) * 3) != 0;
  return count;
}

struct ThreadedRun {
  std::vector<Vec3> start_m, end_m;
  int frames = 0;
  std::string regions_csv;
};

// `case_file` with `overrides` and Solver/Threads = `threads` on the mass-spring backend into
// a scratch directory of its own; the regions' table when `regions`.
ThreadedRun run_with_threads(const std::string& case_file, std::vector<std::string> overrides,
                             int threads, bool regions) {
  const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  const std::string dir = (std::filesystem::temp_directory_path() /
                           ("tightfit_threads_" + test + "_" + std::to_string(threads)))
                              .string();
  overrides.push_back("Solver/Threads=" + std::to_string(threads));
  overrides.push_back("Output/Write VTU=false");
  overrides.push_back("Output/Body pressure=false");
  overrides.push_back(regions ? "Measurements/List=regions" : "Measurements/List=");
  CaseFile file;
  file.read(source_dir + "/" + case_file, overrides);
  std::unique_ptr<Scenario> scenario = make_scenario(file.parameters());
  EXPECT_EQ(scenario->problem.threads, threads);
  ThreadedRun result;
  result.start_m = scenario->initial_positions();
  std::ostringstream log;
  const RunResult run = run_scenario(
      *scenario, [&](const Problem& problem) { return file.create_backend("massspring", problem); },
      dir, log);
  EXPECT_TRUE(run.completed) << run.failure << "\n" << log.str();
  if (run.steps.empty()) return result;
  result.end_m = run.steps.back().state.positions_m;
  result.frames = run.steps.back().report.iterations;
  if (regions) result.regions_csv = file_text(dir + "/regions.csv");
  return result;
}

// The stocking at half resolution (336 vertices; tests/cases/test_garment_regressions.cc,
// CoarseStockingOnMassSpring): frictionless, so each frame's later stages carry the first
// stage's answers.
TEST(Threads, CoarseStockingIsTheSameOnTwoThreads) {
  const std::vector<std::string> coarse = {"Garment/Mesh scale=2"};
  const ThreadedRun one = run_with_threads("cases/stocking_female.prm", coarse, 1, true);
  const ThreadedRun two = run_with_threads("cases/stocking_female.prm", coarse, 2, true);
  ASSERT_FALSE(one.end_m.empty());
  EXPECT_EQ(differing(two.end_m, one.end_m), 0) << "of " << one.end_m.size() << " vertices";
  EXPECT_EQ(two.frames, one.frames);
  EXPECT_FALSE(one.regions_csv.empty());
  EXPECT_EQ(two.regions_csv, one.regions_csv);
}

// A tube held by friction (mu 0.3) under gravity on the smooth surface of a 48-sided prism,
// 30 cm long, stretched to 1.5 times its radius: every stage queries the body and takes the
// return mapping from the step's anchors, and the step's end commits them.
TEST(Threads, FrictionHeldTubeOnAMeshCylinderIsTheSameOnTwoThreads) {
  const double panel_width_m = 0.157, rest_radius_m = 2 * panel_width_m / (2 * M_PI);
  const double rho_m = 1.5 * rest_radius_m;
  const std::string obj = testing::temporary_path("threads_prism.obj");
  std::vector<double> z, radius;
  for (int k = 0; k <= 30; ++k) z.push_back(-0.15 + 0.01 * k), radius.push_back(rho_m);
  testing::write_obj(obj, testing::revolution_surface(z, radius, 48));
  const std::vector<std::string> settings = {
      "Garment/Name=T",
      testing::setting("Garment/Tube/Panel width", panel_width_m),
      "Garment/Tube/Panel height=0.066",
      "Garment/Edge length weft=0.008",
      "Garment/Edge length warp=0.022",
      "Body/Kind=mesh",
      "Body/Mesh/File=" + obj,
      "Body/Mesh/Up axis=+z",
      "Placement/Kind=tube round axis",
      "Placement/Tube round axis/Axis=0,0,1",
      testing::setting("Placement/Tube round axis/Radius", 1.005 * rho_m),
      "Protocol/Final alpha=1",
      "Protocol/Gravity while settling=true",
      "Contact/Friction coefficient=0.3"};
  std::vector<Vec3> end_m[2];
  int frames[2] = {0, 0};
  for (int threads : {1, 2}) {
    std::vector<std::string> with_threads = settings;
    with_threads.push_back("Solver/Threads=" + std::to_string(threads));
    const testing::BodyCaseRun r = testing::run_body_case(with_threads, "massspring");
    EXPECT_TRUE(r.run.completed) << r.run.failure << "\n" << r.log;
    if (r.run.steps.empty()) return;
    EXPECT_GT(r.last().summary.contact_fraction, 0.9);
    end_m[threads - 1] = r.last().state.positions_m;
    frames[threads - 1] = r.last().report.iterations;
  }
  EXPECT_EQ(differing(end_m[1], end_m[0]), 0) << "of " << end_m[0].size() << " vertices";
  EXPECT_EQ(frames[1], frames[0]);
}

// The bodice dressed on the female (cases/top_female_bodice.prm) at 3 cm edges, its coarse copy
// skipped: the placement's dressing alone (the open-seam garment's penalty contact with the
// shrunk body), its sewn garment compared.
TEST(Threads, DressingIsTheSameOnTwoThreads) {
  std::vector<Vec3> dressed[2];
  for (int threads : {1, 2}) {
    CaseFile file;
    file.read(
        source_dir + "/cases/top_female_bodice.prm",
        {"Garment/Pattern file/Mesh edge length=0.03", "Placement/Dressing/Coarse edge length=0",
         "Output/Write VTU=false", "Solver/Threads=" + std::to_string(threads)});
    std::unique_ptr<Scenario> scenario = make_scenario(file.parameters());
    dressed[threads - 1] = scenario->initial_positions();
  }
  ASSERT_FALSE(dressed[0].empty());
  EXPECT_EQ(differing(dressed[1], dressed[0]), 0) << "of " << dressed[0].size() << " vertices";
}

}  // namespace
}  // namespace tightfit
