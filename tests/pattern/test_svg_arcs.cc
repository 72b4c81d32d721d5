// A FreeSewing-style SVG written with relative path commands, smooth curves (s, t) and arcs
// (tests/pattern/data/freesewing_style_relative_arcs.svg): arc lengths against closed forms,
// the pieces meshed and sewn.
#include "pattern/pattern_file.h"
#include "pattern/pattern_garment.h"
#include "tests/pattern/mesh_topology.h"
#include "tests/pattern/sewn_checks.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tightfit::pattern {
namespace {

double edge_length(const Pattern& p, const std::string& panel, const std::string& edge) {
  const PanelOutline& outline = find_panel(p, panel);
  return length_m(outline.edges[find_edge(outline, edge)].segments);
}

// A quarter of the ellipse with semi-axes a and b, by Simpson's rule on 20000 intervals of
// the angle (error far below 1e-12 of the length).
double quarter_ellipse_length(double a, double b) {
  const int n = 20000;
  auto speed = [&](double t) { return std::hypot(a * std::sin(t), b * std::cos(t)); };
  const double h = (M_PI / 2) / n;
  double sum = speed(0) + speed(M_PI / 2);
  for (int k = 1; k < n; ++k) sum += (k % 2 ? 4 : 2) * speed(k * h);
  return sum * h / 3;
}

TEST(SvgArcs, RelativeCommandsAndArcsReadMeshAndSew) {
  Pattern p = read_pattern_file(std::string(TIGHTFIT_PATTERN_TEST_DATA_DIR) +
                                "/freesewing_style_relative_arcs.svg");
  ASSERT_EQ(p.panels.size(), 2u);
  // front: h 300, v -400, a quarter ellipse (60 x 120 mm), h -80, a quarter circle of radius
  // 80 mm, z: six edges, one per command.
  ASSERT_EQ(find_panel(p, "front").edges.size(), 6u);
  EXPECT_NEAR(edge_length(p, "front", "1"), 0.3, 1e-15);
  EXPECT_NEAR(edge_length(p, "front", "2"), 0.4, 1e-15);
  // The ellipse as cubic pieces of 90 degrees: the 4/3 tan(delta / 4) construction's radial
  // error is 2.7e-4 of the radius, the bound taken for the length (measured 1.4e-4).
  EXPECT_NEAR(edge_length(p, "front", "3"), quarter_ellipse_length(0.06, 0.12),
              2.7e-4 * quarter_ellipse_length(0.06, 0.12));
  // The circle is an exact arc: length r pi / 2 less the arc-length table's deficit
  // L sweep^2 / (24 256^2).
  const double quarter = 0.08 * M_PI / 2;
  EXPECT_NEAR(edge_length(p, "front", "5"), quarter * (1 - M_PI * M_PI / 4 / (24.0 * 256 * 256)),
              1e-12);
  // Its midpoint: centre (80, 80) mm (y down), 45 degrees towards (160, 160).
  const Segment& neck = find_panel(p, "front").edges[4].segments[0];
  EXPECT_NEAR(
      (point_at(neck, 0.5) - Vec2(0.08 + 0.08 / std::sqrt(2.0), -0.08 - 0.08 / std::sqrt(2.0)))
          .norm(),
      0.0, 1e-12);
  // back: l 300,0 and its implicit second pair 0,-400, c, s, q, t, z: seven edges. The s
  // reflects the c's second control point (600, 100) through (560, 80): (520, 60).
  const PanelOutline& back = find_panel(p, "back");
  ASSERT_EQ(back.edges.size(), 7u);
  EXPECT_NEAR(edge_length(p, "back", "2"), 0.4, 1e-15);
  const Segment& s = back.edges[3].segments[0];
  EXPECT_EQ(s.kind, Segment::Kind::cubic);
  EXPECT_NEAR((s.control1 - Vec2(0.52, -0.06)).norm(), 0.0, 1e-15);
  // The t reflects the q's control (440, 60) through (400, 100): (360, 140).
  const Segment& t = back.edges[5].segments[0];
  EXPECT_EQ(t.kind, Segment::Kind::quadratic);
  EXPECT_NEAR((t.control1 - Vec2(0.36, -0.14)).norm(), 0.0, 1e-15);

  p.seams = parse_seam_list("front:2 -- back:7 reversed; front:6 reversed -- back:2");
  validate(p);
  expect_sews_into(p, 0.02, 2);
}

}  // namespace
}  // namespace tightfit::pattern
