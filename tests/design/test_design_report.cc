// The final design's report with a check on another backend (docs/design.md, "What it writes";
// Design/Check backend): the check's band means are written beside the design's, its error is
// its own mean minus the target, and the bands farther than the check's tolerance from their
// target are named. Bookkeeping only: the bands are made up here, no simulation runs (the
// check on the FE backend itself is the command's, tests/design/CMakeLists.txt).
#include "cases/design/design_report.h"

#include "io/csv_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>

namespace tightfit {
namespace {

const double kPaPerMmHg = 133.322387415;

// Three points with targets 20, 16, 12 mmHg, and a last iteration whose means are 19.8, 16.1,
// 12.0 mmHg (peaks 40, 30, 20).
struct Report {
  DesignProblem problem;
  DesignIteration last;
};

Report report() {
  Report r;
  r.problem.points = {{"B", 0.03}, {"C", 0.10}, {"G", 0.17}};
  r.problem.girths_m = {0.29, 0.31, 0.34};
  for (double t : {20.0, 16.0, 12.0}) r.problem.targets_Pa.push_back(t * kPaPerMmHg);
  const double means[] = {19.8, 16.1, 12.0}, peaks[] = {40, 30, 20};
  for (int k = 0; k < 3; ++k) {
    DesignBand b;
    b.circumference_m = 0.2 + 0.03 * k;
    b.laplace_Pa = (means[k] + 0.5) * kPaPerMmHg;
    b.mean_Pa = means[k] * kPaPerMmHg;
    b.peak_Pa = peaks[k] * kPaPerMmHg;
    r.last.bands.push_back(b);
  }
  return r;
}

// A check 0.9 mmHg above B's target, 1.2 below C's, and without contact at G (NaN).
DesignCheck check() {
  DesignCheck c;
  c.backend = "fem";
  c.tolerance_Pa = 1.0 * kPaPerMmHg;
  c.bands = {{20.9 * kPaPerMmHg, 41 * kPaPerMmHg},
             {14.8 * kPaPerMmHg, 29 * kPaPerMmHg},
             {std::numeric_limits<double>::quiet_NaN(), 0.0}};
  return c;
}

TEST(DesignReport, CheckNamesTheBandsOutsideItsTolerance) {
  const Report r = report();
  EXPECT_EQ(check_outside(r.problem, check()), (std::vector<std::string>{"C", "G"}));
  DesignCheck close = check();
  close.bands[1].mean_Pa = 15.1 * kPaPerMmHg;
  close.bands[2].mean_Pa = 12.99 * kPaPerMmHg;
  EXPECT_TRUE(check_outside(r.problem, close).empty());
  // No check, or one that did not finish: nothing measured, nothing named.
  DesignCheck none;
  none.backend = "fem";
  none.failure = "stalled";
  EXPECT_TRUE(check_outside(r.problem, none).empty());
  DesignCheck short_check = check();
  short_check.bands.pop_back();
  EXPECT_THROW(check_outside(r.problem, short_check), std::invalid_argument);
}

// design.csv holds the design's mean and the check's mean each in its own column, the check's
// error against the target (to the CSV's 10 digits: 1e-8 mmHg), and no check columns without
// a finished check.
TEST(DesignReport, CsvHoldsTheCheckBesideTheDesign) {
  const Report r = report();
  const std::string path =
      (std::filesystem::temp_directory_path() / "tightfit_design_report.csv").string();
  write_design_csv(path, r.problem, r.last, check());
  const std::optional<CsvRows> csv = CsvRows::read(path);
  ASSERT_TRUE(csv);
  ASSERT_EQ(csv->n_rows(), 3u);
  const double means[] = {19.8, 16.1, 12.0}, checks[] = {20.9, 14.8}, targets[] = {20, 16, 12};
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(csv->text(k, csv->column("point")), r.problem.points[k].name);
    EXPECT_NEAR(csv->number(k, csv->column("mean_mmHg")), means[k], 1e-8);
    EXPECT_NEAR(csv->number(k, csv->column("target_mmHg")), targets[k], 1e-8);
    if (k < 2) {
      EXPECT_NEAR(csv->number(k, csv->column("check_mean_mmHg")), checks[k], 1e-8);
      EXPECT_NEAR(csv->number(k, csv->column("check_error_mmHg")), checks[k] - targets[k], 1e-8);
    } else {
      EXPECT_TRUE(std::isnan(csv->number(k, csv->column("check_mean_mmHg"))));
    }
  }
  DesignCheck failed = check();
  failed.bands.clear();
  failed.failure = "stalled";
  write_design_csv(path, r.problem, r.last, failed);
  const std::optional<CsvRows> without = CsvRows::read(path);
  ASSERT_TRUE(without);
  EXPECT_THROW(without->column("check_mean_mmHg"), std::runtime_error);
  std::filesystem::remove(path);
}

// The table on screen names the check's backend in its columns.
TEST(DesignReport, TableNamesTheCheckBackend) {
  const Report r = report();
  std::ostringstream text;
  text << design_table("design", r.problem, r.last, check());
  EXPECT_NE(text.str().find("fem mean"), std::string::npos) << text.str();
  EXPECT_NE(text.str().find("20.90"), std::string::npos) << text.str();
  EXPECT_NE(text.str().find("-1.20"), std::string::npos) << text.str();
}

}  // namespace
}  // namespace tightfit
