// Which settle a case's entries at auto take (cases/case_parameters.cc, rough_mesh_body;
// docs/dressing.md, "Settling the top"): the rough mesh body's (the rms residual at 3e-3 of the
// tension scale, no contact-load rule, a gap of 1e-6 m) on a body mesh touched on its flat faces
// or, on its smooth surface, by a garment held by friction; the cylinder's (the largest residual
// at 1e-4, the contact-load rule at 1e-4, 1e-8 m) on a frictionless one. The numbers are the
// documented defaults of docs/parameters.md.
#include "cases/case_parameters.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace tightfit {
namespace {

StopRule rule_of(const std::string& case_name, const std::vector<std::string>& overrides) {
  CaseFile file;
  file.read(std::string(TIGHTFIT_CASES_DIR) + "/" + case_name, overrides);
  return file.parameters().stop_rule;
}

void expect_rough_mesh_body_rule(const StopRule& rule, bool rough) {
  EXPECT_EQ(rule.rough_mesh_body, rough);
  EXPECT_EQ(rule.norm, rough ? StopNorm::rms : StopNorm::largest);
  EXPECT_EQ(rule.relative_tolerance, rough ? 3e-3 : 1e-4);
  EXPECT_EQ(rule.contact_load_tolerance, rough ? 0.0 : 1e-4);
  EXPECT_EQ(rule.gap_tolerance_m, rough ? 1e-6 : 1e-8);
}

TEST(SettleRuleOnMeshBodies, FrictionOrFlatFacesTakeTheRoughMeshBodysRule) {
  // The male top: the smooth surface (its default) with friction 0.3.
  expect_rough_mesh_body_rule(rule_of("top_male.prm", {}), true);
  expect_rough_mesh_body_rule(rule_of("top_male.prm", {"Body/Mesh/Contact surface=faceted"}), true);
  expect_rough_mesh_body_rule(rule_of("top_male.prm", {"Contact/Friction coefficient=0"}), false);
  expect_rough_mesh_body_rule(rule_of("top_male.prm", {"Contact/Friction coefficient=0",
                                                       "Body/Mesh/Contact surface=faceted"}),
                              true);
  // The stocking: smooth, frictionless.
  expect_rough_mesh_body_rule(rule_of("stocking_female.prm", {}), false);
  // A given number wins on either.
  EXPECT_EQ(rule_of("top_male.prm", {"Solver/Relative tolerance=1e-3"}).relative_tolerance, 1e-3);
}

}  // namespace
}  // namespace tightfit
