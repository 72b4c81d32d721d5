// End-to-end regressions: the cases users care about, on a coarse garment mesh, run to the end
// on each backend, their region means (regions.csv) against the values this code measured. A
// change in any stage (placement, contact, either solver, the extractor, the regions) moves
// them; a change within a stop rule moves them by less than the stated tolerance.
#include "cases/case_parameters.h"
#include "cases/scenario.h"
#include "cases/scenario_run.h"
#include "csv_rows.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace tightfit {
namespace {

const std::string source_dir = TIGHTFIT_SOURCE_DIR;

// Runs `case_file` with `overrides` on `backend` into a scratch directory; returns each
// region's mean pressure at the last step, Pa (an empty map when the run failed).
std::map<std::string, double> region_means_Pa(const std::string& case_file,
                                              std::vector<std::string> overrides,
                                              const std::string& backend) {
  const std::string dir = (std::filesystem::temp_directory_path() /
                           ("tightfit_regression_" + backend + "_" +
                            std::filesystem::path(case_file).stem().string()))
                              .string();
  overrides.push_back("Solver/Backend=" + backend);
  overrides.push_back("Output/Write VTU=false");
  overrides.push_back("Measurements/List=regions");
  CaseFile file;
  file.read(source_dir + "/" + case_file, overrides);
  std::unique_ptr<Scenario> setup = make_scenario(file.parameters());
  std::ostringstream log;
  const RunResult run = run_scenario(
      *setup,
      [&](const Problem& problem) { return file.create_backend(backend, problem); }, dir, log);
  EXPECT_TRUE(run.completed) << run.failure << "\n" << log.str();
  std::map<std::string, double> means;
  if (!run.completed) return means;
  for (const auto& row : testing::read_csv(dir + "/regions.csv"))
    if (std::stoi(row.at("step")) == run.steps.back().step)
      means[row.at("region")] = std::stod(row.at("p_mean_Pa"));
  for (const auto& [region, mean] : means)
    std::printf("%s on %s: region %s p_mean %.6f Pa\n", case_file.c_str(), backend.c_str(),
                region.c_str(), mean);
  return means;
}

void expect_means(const std::map<std::string, double>& measured,
                  const std::map<std::string, double>& expected, double relative_tolerance) {
  for (const auto& [region, mean_Pa] : expected) {
    ASSERT_EQ(measured.count(region), 1u) << "region " << region;
    EXPECT_NEAR(measured.at(region), mean_Pa, relative_tolerance * mean_Pa) << "region " << region;
  }
}

// The stocking (cases/stocking_female.prm) on the leg at twice its edges (16 mm round the leg,
// 30 mm along it), the body file given from the source tree.
std::vector<std::string> coarse_stocking() {
  return {"Garment/Edge length weft=0.016", "Garment/Edge length warp=0.03",
          "Body/Mesh/File=" + source_dir + "/data/bodies/makehuman_default_female_body_m.obj"};
}

}  // namespace
}  // namespace tightfit
