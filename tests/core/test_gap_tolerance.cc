// The gap tolerance tied to the stop rule (core/load_step.h, StopRule::resolvable_gap_m;
// docs/backends.md, "The gap the stop rule resolves"): the residual e Y h^2 / L a settle may
// leave, over the stiffness Y of a vertex the membrane alone holds, is e h^2 / L.
#include "core/load_step.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tightfit {
namespace {

// The stocking's mesh (docs/stocking.md): mean rest edge 1.35 cm, rest area 0.1599 m^2 (the
// girth table times one minus the ease, integrated along the tube); its half-resolution mesh
// 2.68 cm. By hand: 1e-4 * 0.0135^2 / sqrt(0.1599) = 4.5576e-8 m, and 1.7961e-7 m.
constexpr double stocking_edge_m = 0.0135, coarse_edge_m = 0.0268, stocking_area_m2 = 0.1599;

TEST(GapTolerance, TheStopRulesResolvableGapOfTheStockingsMeshes) {
  StopRule rule;  // the relative rule at its default, 1e-4
  EXPECT_NEAR(rule.resolvable_gap_m(stocking_edge_m, stocking_area_m2), 4.5576e-8, 1e-12);
  EXPECT_NEAR(rule.resolvable_gap_m(coarse_edge_m, stocking_area_m2), 1.7961e-7, 1e-11);
  // Linear in the tolerance: a threefold tighter rule resolves a threefold smaller gap.
  StopRule tight;
  tight.relative_tolerance = 1e-4 / 3;
  EXPECT_NEAR(tight.resolvable_gap_m(coarse_edge_m, stocking_area_m2),
              rule.resolvable_gap_m(coarse_edge_m, stocking_area_m2) / 3, 1e-20);
}

TEST(GapTolerance, AutoIsRaisedToTheResolvableGapAndASetValueStays) {
  StopRule automatic;
  automatic.gap_tolerance_auto = true;
  automatic.raise_gap_tolerance_to_stop_rule(coarse_edge_m, stocking_area_m2);
  EXPECT_DOUBLE_EQ(automatic.gap_tolerance_m,
                   automatic.resolvable_gap_m(coarse_edge_m, stocking_area_m2));
  // A fine mesh resolves less than the default 1e-8 m: the default stays.
  StopRule fine;
  fine.gap_tolerance_auto = true;
  fine.raise_gap_tolerance_to_stop_rule(0.001, 1.0);  // 1e-4 * 1e-6 / 1 = 1e-10 m
  EXPECT_EQ(fine.gap_tolerance_m, 1e-8);
  // The FE backend's own rule alone (relative tolerance 0) resolves no gap of its own.
  StopRule own_rule;
  own_rule.gap_tolerance_auto = true;
  own_rule.relative_tolerance = 0;
  own_rule.raise_gap_tolerance_to_stop_rule(coarse_edge_m, stocking_area_m2);
  EXPECT_EQ(own_rule.gap_tolerance_m, 1e-8);
  // A value the case sets is used as given.
  StopRule set;
  set.gap_tolerance_m = 1e-9;
  set.raise_gap_tolerance_to_stop_rule(coarse_edge_m, stocking_area_m2);
  EXPECT_EQ(set.gap_tolerance_m, 1e-9);
}

}  // namespace
}  // namespace tightfit
