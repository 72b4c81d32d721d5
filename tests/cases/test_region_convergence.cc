// Convergence by region (cases/region_convergence.h) against manufactured sequences: each
// region's mean and peak pressure f(h) = f0 + C h^p with its own limit, constant and order, so
// that the observed order, the Richardson estimate and the GCI of every region are known in
// closed form.
#include "cases/region_convergence.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace tightfit {
namespace {

struct Power {
  double f0, c, p;
  double operator()(double h) const { return f0 + c * std::pow(h, p); }
};

struct ManufacturedRegion {
  std::string name;
  Power mean, peak;
};

// Levels of edge h0, h0/r, h0/r^2, ...: the edges and every region's values on each.
struct Levels {
  std::vector<double> edges_m;
  std::vector<std::vector<RegionLevelPressure>> pressures;
};
Levels sample(const std::vector<ManufacturedRegion>& regions, double h0, double ratio, int n) {
  Levels l;
  for (int i = 0; i < n; ++i) {
    const double h = h0 / std::pow(ratio, i);
    l.edges_m.push_back(h);
    std::vector<RegionLevelPressure> level;
    for (const ManufacturedRegion& r : regions) level.push_back({r.mean(h), r.peak(h)});
    l.pressures.push_back(level);
  }
  return l;
}

std::vector<std::string> names_of(const std::vector<ManufacturedRegion>& regions) {
  std::vector<std::string> names;
  for (const ManufacturedRegion& r : regions) names.push_back(r.name);
  return names;
}

// Three regions as a stocking's B, C, G might read (Pa): the mean converging from below at
// second order, the peak from above at first order, each with its own limit.
const std::vector<ManufacturedRegion> stocking_like = {
    {"B", {3300.0, -4.0e5, 2.0}, {12000.0, 6.0e4, 1.0}},
    {"C", {1700.0, 2.5e5, 2.0}, {3400.0, -2.0e4, 1.0}},
    {"G", {900.0, -1.0e5, 1.5}, {2100.0, 3.0e4, 0.5}},
};

TEST(RegionConvergence, EachRegionGivesItsOwnOrderLimitAndGci) {
  for (double ratio : {2.0, std::sqrt(2.0)}) {
    const double h0 = 0.027;
    const Levels l = sample(stocking_like, h0, ratio, 3);
    const std::vector<RegionConvergence> rows =
        estimate_region_convergence(names_of(stocking_like), l.edges_m, l.pressures, 2.0);
    ASSERT_EQ(rows.size(), stocking_like.size());
    const double h = h0 / (ratio * ratio);  // the finest level's edge
    for (std::size_t k = 0; k < rows.size(); ++k) {
      const ManufacturedRegion& m = stocking_like[k];
      const RegionConvergence& r = rows[k];
      SCOPED_TRACE(r.region + ", ratio " + std::to_string(ratio));
      EXPECT_EQ(r.region, m.name);
      EXPECT_EQ(r.n_levels, 3);
      EXPECT_NEAR(r.ratio, ratio, 1e-12);
      EXPECT_DOUBLE_EQ(r.edge_fine_m, h);
      EXPECT_DOUBLE_EQ(r.mean_fine_Pa, m.mean(h));
      EXPECT_DOUBLE_EQ(r.peak_fine_Pa, m.peak(h));
      // A pure power: the order and the limit exactly (rounding aside: 1e-8 of the values).
      EXPECT_TRUE(r.mean.order_observed);
      EXPECT_NEAR(r.mean.order, m.mean.p, 1e-8);
      EXPECT_NEAR(r.peak.order, m.peak.p, 1e-8);
      EXPECT_NEAR(r.mean.extrapolated, m.mean.f0, 1e-8 * m.mean.f0);
      EXPECT_NEAR(r.peak.extrapolated, m.peak.f0, 1e-8 * m.peak.f0);
      // GCI = 1.25 |f_medium - f_fine| / |f_fine| / (r^p - 1) = 1.25 |C h^p| / |f_fine|.
      EXPECT_DOUBLE_EQ(r.mean.safety_factor, 1.25);
      EXPECT_NEAR(r.mean.gci_fine, 1.25 * std::abs(m.mean.c * std::pow(h, m.mean.p)) / m.mean(h),
                  1e-9);
      EXPECT_NEAR(r.peak.gci_fine, 1.25 * std::abs(m.peak.c * std::pow(h, m.peak.p)) / m.peak(h),
                  1e-9);
    }
  }
}

TEST(RegionConvergence, MoreLevelsUseTheFinestThree) {
  // Four levels; the coarsest is spoiled: the estimate reads the finest three only.
  Levels l = sample(stocking_like, 0.04, 2.0, 4);
  l.pressures[0][0].mean_Pa = 1.0;
  const std::vector<RegionConvergence> rows =
      estimate_region_convergence(names_of(stocking_like), l.edges_m, l.pressures, 2.0);
  EXPECT_EQ(rows[0].n_levels, 4);
  EXPECT_NEAR(rows[0].mean.order, 2.0, 1e-8);
  EXPECT_NEAR(rows[0].mean.extrapolated, 3300.0, 1e-8 * 3300.0);
}

TEST(RegionConvergence, TwoLevelsAssumeTheFormalOrder) {
  // f = f0 + C h^2 on two levels: with the assumed order 2 Richardson's value is the limit, and
  // the GCI carries Roache's safety factor 3.
  const std::vector<ManufacturedRegion> second_order = {
      {"calf", {1650.0, 3.0e5, 2.0}, {3300.0, -1.0e5, 2.0}}};
  const Levels l = sample(second_order, 0.02, 2.0, 2);
  const RegionConvergence r =
      estimate_region_convergence({"calf"}, l.edges_m, l.pressures, 2.0).front();
  EXPECT_FALSE(r.mean.order_observed);
  EXPECT_DOUBLE_EQ(r.mean.order, 2.0);
  EXPECT_DOUBLE_EQ(r.mean.safety_factor, 3.0);
  EXPECT_NEAR(r.mean.extrapolated, 1650.0, 1e-9 * 1650.0);
  EXPECT_NEAR(r.peak.extrapolated, 3300.0, 1e-9 * 3300.0);
  const double h = 0.01;
  EXPECT_NEAR(r.mean.gci_fine, 3.0 * 3.0e5 * h * h / (1650.0 + 3.0e5 * h * h), 1e-12);
}

TEST(RegionConvergence, MeasuredRatioIsTheGeometricMeanOfTheFinestLevels) {
  // Whole numbers of divisions: edges that shrink by 2.1 then 1.9; the estimate uses sqrt(3.99).
  EXPECT_NEAR(measured_refinement_ratio({0.04, 0.04 / 2.1, 0.04 / 2.1 / 1.9}), std::sqrt(2.1 * 1.9),
              1e-12);
  EXPECT_NEAR(measured_refinement_ratio({0.05, 0.03}), 0.05 / 0.03, 1e-12);
  EXPECT_NEAR(measured_refinement_ratio({1.0, 0.08, 0.04, 0.02}), 2.0, 1e-12);
  EXPECT_THROW(measured_refinement_ratio({0.01}), std::invalid_argument);
}

TEST(RegionConvergence, RegionWithoutContactReadsNoEstimateAndSparesTheOthers) {
  // The garment misses one region on the coarsest level (NaN there): its estimates are NaN,
  // the other regions' unchanged.
  Levels l = sample(stocking_like, 0.027, 2.0, 3);
  l.pressures[0][1] = RegionLevelPressure{};
  const std::vector<RegionConvergence> rows =
      estimate_region_convergence(names_of(stocking_like), l.edges_m, l.pressures, 2.0);
  EXPECT_TRUE(std::isnan(rows[1].mean.order));
  EXPECT_TRUE(std::isnan(rows[1].mean.extrapolated));
  EXPECT_TRUE(std::isnan(rows[1].peak.gci_fine));
  EXPECT_NEAR(rows[0].mean.extrapolated, 3300.0, 1e-8 * 3300.0);
  EXPECT_NEAR(rows[2].peak.order, 0.5, 1e-8);
}

TEST(RegionConvergence, MismatchedInputIsRefused) {
  const Levels l = sample(stocking_like, 0.027, 2.0, 3);
  EXPECT_THROW(estimate_region_convergence({"B", "C"}, l.edges_m, l.pressures, 2.0),
               std::invalid_argument);
  EXPECT_THROW(estimate_region_convergence(names_of(stocking_like), {0.02, 0.01}, l.pressures, 2.0),
               std::invalid_argument);
  const Levels one = sample(stocking_like, 0.027, 2.0, 1);
  EXPECT_THROW(
      estimate_region_convergence(names_of(stocking_like), one.edges_m, one.pressures, 2.0),
      std::invalid_argument);
}

}  // namespace
}  // namespace tightfit
