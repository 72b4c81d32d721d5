// A GarmentCode panel's 3D arrangement carried to the meshed panel (pattern_garment.h,
// Garment::Panel::arrangement; docs/arrangement.md "Arrangement from the pattern file"). In the
// jumpsuit's file the left and right front torso panels meet at the centre front, and the two
// back ones at the centre back, edge on edge (GarmentCode places them 0.0 cm apart): every
// meshed vertex pair those seams join must then coincide in 3D, whatever the reader did to the
// outlines (mirroring a clockwise one, shifting a grid panel) and with ease.
#include "pattern/pattern_file.h"
#include "pattern/pattern_garment.h"

#include <gtest/gtest.h>

namespace tightfit::pattern {
namespace {

Vec3 arranged(const Panel& panel, int vertex) {
  const Vec2& r = panel.rest_positions_m[vertex];
  return panel.arrangement->rotation * Vec3(r.x(), r.y(), 0) + panel.arrangement->translation_m;
}

void expect_centre_seams_meet(double ease_weft, double ease_warp, double tolerance_m) {
  Pattern p = read_pattern_file(
      std::string(TIGHTFIT_PATTERNS_DIR) + "/garmentcode_jumpsuit_mean_all_specification.json", {});
  p.ease_weft = ease_weft;
  p.ease_warp = ease_warp;
  PatternMeshOptions options;
  options.edge_length_m = 0.03;
  const Garment g = pattern_garment(p, options);
  int checked = 0;
  for (const Seam& seam : g.seams) {
    const Panel& a = g.panels[seam.panel_a];
    const Panel& b = g.panels[seam.panel_b];
    const bool centre = (a.name == "right_ftorso" && b.name == "left_ftorso") ||
                        (a.name == "right_btorso" && b.name == "left_btorso");
    if (!centre) continue;
    ASSERT_TRUE(a.arrangement && b.arrangement);
    const auto& ea = a.edges.at(seam.edge_a);
    const auto& eb = b.edges.at(seam.edge_b);
    ASSERT_EQ(ea.size(), eb.size());
    for (std::size_t k = 0; k < ea.size(); ++k) {
      const int vb = seam.reversed ? eb[eb.size() - 1 - k] : eb[k];
      EXPECT_NEAR((arranged(a, ea[k]) - arranged(b, vb)).norm(), 0.0, tolerance_m)
          << a.name << " -- " << b.name << " pair " << k;
      ++checked;
    }
  }
  EXPECT_GT(checked, 10);
}

TEST(GarmentCodeArrangement, CentreSeamsMeetAsTheFileArrangesThem) {
  // Without ease the meshed edges are the file's: the pairs coincide to round-off (1e-9 m).
  expect_centre_seams_meet(1.0, 1.0, 1e-9);
}

TEST(GarmentCodeArrangement, EasedPanelsKeepTheirCentres) {
  // With ease each panel shrinks about its own centre: the centre seam's pairs, at most 0.3 m
  // from their panel's centre, part by at most twice 10 % of that: 0.06 m allowed.
  expect_centre_seams_meet(0.9, 0.9, 0.06);
}

}  // namespace
}  // namespace tightfit::pattern
