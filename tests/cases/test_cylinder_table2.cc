// The paper's garment T with its Table 2 fabric (cases/cylinder_T_table2.prm, the tensile
// curves law) on both backends at alpha = 1.2, 1.5 and 1.8, read three ways:
//   - the mean pressure against the closed form, hoop force read off the course curve at
//     strain alpha - 1 over b alpha R0 (cases/cylinder_theory.h);
//   - the 11 virtual air-pack sensors of sensors.csv against the mean pressure;
//   - the 11 stamps' Eq. 3 of stamps.csv against the simulated pressure at each stamp centre.
// Measured (mass-spring | FEM), mean against closed form: -0.67 | -0.67% at alpha 1.2,
// -0.37 | -0.38% at 1.5, -0.32 | -0.31% at 1.8 (the tube reads low: linear triangles inscribe
// a polygon in the circle, and d ln T / d ln alpha = 6 at alpha 1.2 magnifies the 0.1%
// shortfall in hoop stretch); sensors against the mean: within 6e-5; Eq. 3 against the
// simulated pressure: -0.16% at alpha 1.2, -0.09% at 1.8, every stamp.
#include "cases/case_parameters.h"
#include "cases/scenario.h"
#include "cases/scenario_run.h"
#include "csv_rows.h"
#include "cylinder_start.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace tightfit {
namespace {

class CylinderTable2 : public ::testing::TestWithParam<const char*> {};

TEST_P(CylinderTable2, ClosedFormSensorsAndStampsAgree) {
  const std::string backend = GetParam();
  const std::filesystem::path out =
      std::filesystem::temp_directory_path() / ("tightfit_cylinder_table2_" + backend);
  std::filesystem::remove_all(out);
  CaseFile file;
  file.read(
      TIGHTFIT_CASES_DIR "/cylinder_T_table2.prm",
      {"Output/Write VTU=false", "Measurements/List=cylinder theory, air-pack sensors, stamps"});
  // Start on a cylinder at alpha 1.2 and grow it to 1.5 and 1.8.
  const std::vector<double> alphas = {1.2, 1.5, 1.8};
  testing::start_cylinder_at(file, alphas.front(), 2 * 0.157 / (2 * M_PI));
  std::unique_ptr<Scenario> scenario = make_scenario(file.parameters());
  scenario->alphas = alphas;
  std::ostringstream log;
  const RunResult run = run_scenario(
      *scenario, [&](const Problem& problem) { return file.create_backend(backend, problem); },
      out.string(), log);
  ASSERT_TRUE(run.completed) << run.failure << "\n" << log.str();
  ASSERT_EQ(run.steps.size(), alphas.size());

  std::map<int, double> mean_Pa;
  for (const StepMeasurement& m : run.steps) {
    std::printf("%s: alpha %.1f  p %.2f Pa  closed form %.2f Pa  error %+.3f%%\n", backend.c_str(),
                m.alpha, m.p_mean_Pa(), m.p_theory_Pa, 100 * m.rel_error);
    // Linear triangles inscribe a polygon in the circle: the pressure reads low, measured
    // -0.31% to -0.67% on both backends (the header); one-sided, tolerance -1%.
    EXPECT_LT(m.rel_error, 0.0) << "alpha " << m.alpha;
    EXPECT_GT(m.rel_error, -0.01) << "alpha " << m.alpha;
    EXPECT_EQ(m.summary.contact_fraction, 1.0);
    mean_Pa[m.step] = m.p_mean_Pa();
  }

  const auto sensors = testing::read_csv((out / "sensors.csv").string());
  ASSERT_EQ(sensors.size(), 11 * alphas.size());
  double worst_sensor = 0.0, covered_range[2] = {2.0, 0.0}, worst_grain_deg = 0.0;
  for (const auto& row : sensors) {
    const double mean = mean_Pa.at(std::stoi(row.at("step")));
    const double error = std::stod(row.at("p_sensor_Pa")) / mean - 1.0;
    worst_sensor = std::max(worst_sensor, std::abs(error));
    // The garment covers the disc: the area found over it is pi d^2 / 4 plus the curved
    // surface's excess and the sub-triangles' cut, which goes either way (measured -0.38% to
    // +0.67% over both backends and all steps); tolerance 1%.
    const double covered = std::stod(row.at("covered_area_m2")) / (M_PI * 0.0075 * 0.0075);
    covered_range[0] = std::min(covered_range[0], covered);
    covered_range[1] = std::max(covered_range[1], covered);
    EXPECT_NEAR(covered, 1.0, 0.01);
    // The uniform state: measured within 6e-5 of the mean; tolerance 2e-4.
    EXPECT_LT(std::abs(error), 2e-4) << row.at("sensor") << " step " << row.at("step");
  }
  double worst_stamp = 0.0;
  const auto stamps = testing::read_csv((out / "stamps.csv").string());
  ASSERT_EQ(stamps.size(), 11 * alphas.size());
  for (const auto& row : stamps) {
    const double difference = std::stod(row.at("rel_difference"));
    worst_stamp = std::max(worst_stamp, std::abs(difference));
    // Measured at most 0.16%; tolerance 0.3%.
    EXPECT_LT(std::abs(difference), 0.003) << row.at("stamp") << " step " << row.at("step");
    // The hoop is the weft: the largest stretch lies along it (measured within 0.0097 degrees
    // on the mass-spring backend, 5e-9 on the FE backend); tolerance 0.02 degrees.
    const double grain_deg = std::abs(std::stod(row.at("grain_angle_max_deg")));
    worst_grain_deg = std::max(worst_grain_deg, grain_deg);
    EXPECT_LT(grain_deg, 0.02);
  }
  std::printf(
      "%s: worst sensor %.2e, worst stamp %.2e, covered area / disc %.5f to %.5f, grain angle of "
      "the largest stretch up to %.3g deg\n",
      backend.c_str(), worst_sensor, worst_stamp, covered_range[0], covered_range[1],
      worst_grain_deg);
  std::filesystem::remove_all(out);
}

INSTANTIATE_TEST_SUITE_P(BothBackends, CylinderTable2, ::testing::Values("massspring", "fem"));

}  // namespace
}  // namespace tightfit
