// The stop rule measured also against the step's contact load (core/load_step.h,
// StopRule::threshold_N; docs/backends.md, "The stop rule at the contact load"):
//   threshold = min(rule, max(0.1 rule, c F)),  F = contact force sum / vertices in contact.
#include "core/load_step.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace tightfit {
namespace {

// The cylinder 4 5T case at alpha 1.05, its first contact step (cases/cylinder_45T.prm;
// solver.log of `tightfit run`): the tension-scale rule 1e-4 Y h^2 / L = 1.35237e-5 N, and 552
// vertices in contact carrying 9.6324 N in all, F = 0.01745 N each (about 103 Pa on their
// 1.70e-4 m^2). By hand: c F = 1e-4 x 0.01745 N = 1.745e-6 N, above the floor 1.35237e-6 N.
TEST(ContactLoadRule, TightensTheTensionRuleToTheContactLoadOfTheFirstContactStep) {
  const double rule_N = 1.35237e-5, load_N = 9.6324, vertex_force_N = load_N / 552;
  StopRule rule;  // Contact load tolerance at its default, 1e-4
  EXPECT_NEAR(rule.threshold_N(rule_N, load_N, 552), 1.745e-6, 1e-12);
  // The pressure error each allows, at most the threshold over a vertex's force: 1e-4 of the
  // pressure, where the tension rule alone allowed 1.35237e-5 / 0.01745 = 7.75e-4.
  EXPECT_NEAR(rule.threshold_N(rule_N, load_N, 552) / vertex_force_N, 1e-4, 1e-12);
  EXPECT_NEAR(rule_N / vertex_force_N, 7.75e-4, 1e-6);
}

TEST(ContactLoadRule, TheTensionRuleWhereItIsTighterOffOrOutOfContact) {
  StopRule rule;
  // About 1150 Pa at alpha 1.8: 0.195 N a vertex, c F = 1.95e-5 N, looser than 1.35237e-5 N.
  EXPECT_EQ(rule.threshold_N(1.35237e-5, 552 * 0.195, 552), 1.35237e-5);
  EXPECT_EQ(rule.threshold_N(1.35237e-5, 0.0, 0), 1.35237e-5);  // the garment hangs loose
  StopRule off;
  off.contact_load_tolerance = 0.0;
  EXPECT_EQ(off.threshold_N(1.35237e-5, 9.6324, 552), 1.35237e-5);
}

TEST(ContactLoadRule, NeverBelowATenthOfTheTensionRule) {
  StopRule rule;
  // One vertex touching with 1e-3 N: c F = 1e-7 N, below the floor 0.1 x 1.35237e-5 N.
  EXPECT_DOUBLE_EQ(rule.threshold_N(1.35237e-5, 1e-3, 1), 1.35237e-6);
  // A negative or out-of-range tolerance is refused, naming the entry.
  StopRule negative;
  negative.contact_load_tolerance = -1e-4;
  try {
    negative.validate(false);
    FAIL() << "a negative Contact load tolerance was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("Solver/Contact load tolerance"), std::string::npos);
  }
}

}  // namespace
}  // namespace tightfit
