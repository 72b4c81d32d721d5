// The tapered tube (core/tapered_tube_garment.h): every row's rest length round the ring is the
// relaxed girth of its height (given, or the body's times 1 - ease), the rows divide evenly, the
// seams close, and ring_coordinates reads the girths and shares back; bad shapes are refused
// naming the entry.
#include "core/tapered_tube_garment.h"
#include "core/tube_garment.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

namespace tightfit {
namespace {

TaperedTubeShape stocking_like() {
  TaperedTubeShape shape;
  shape.length_m = 0.5;
  shape.n_panels = 3;
  shape.girths_m = PiecewiseLinear({{0.0, 0.20}, {0.2, 0.35}, {0.5, 0.50}}, "Girths");
  shape.negative_ease = PiecewiseLinear({{0.0, 0.25}, {0.5, 0.15}}, "Negative ease");
  return shape;
}

TEST(TaperedTube, RowsTakeTheRelaxedGirthOfTheirHeight) {
  const TaperedTubeShape shape = stocking_like();
  // By hand: at 0.1 m the body's girth is 0.275 m, the ease 0.23.
  EXPECT_NEAR(shape.relaxed_girth_m(0.1), 0.275 * (1 - 0.23), 1e-15);
  EXPECT_NEAR(shape.relaxed_girth_m(-1.0), 0.20 * 0.75, 1e-15);  // constant beyond the ends
  const Garment g = make_tapered_tube_garment("stocking", shape, MeshSpacing{0.01, 0.02});
  const SimulationMesh mesh = weld(g);
  // The rest length of every row round the ring: the sum of its rest edges.
  std::map<long, double> row_length;
  for (const auto& corners : mesh.rest_triangles)
    for (int k = 0; k < 3; ++k) {
      const Vec2& a = corners[k];
      const Vec2& b = corners[(k + 1) % 3];
      if (std::abs(a.y() - b.y()) < 1e-12) row_length[std::lround(1e6 * a.y())] += (b - a).norm();
    }
  ASSERT_EQ(row_length.size(), 26u);  // 0.5 m in rows of 0.02 m
  for (const auto& [micrometres, length] : row_length) {
    const double h = 1e-6 * micrometres;
    // Inner rows are edges of two triangles, the bottom and top rows of one.
    const double counted = (micrometres == 0 || micrometres == 500000) ? 1.0 : 2.0;
    EXPECT_NEAR(length / counted, shape.relaxed_girth_m(h), 1e-12) << "row at " << h << " m";
  }
  // Sewn into one closed ring: as many bottom vertices as bottom edges.
  std::size_t bottom_edges = 0;
  for (const auto& corners : mesh.rest_triangles)
    for (int k = 0; k < 3; ++k)
      if (corners[k].y() == 0.0 && corners[(k + 1) % 3].y() == 0.0) ++bottom_edges;
  EXPECT_EQ(mesh.vertex_groups.at("bottom").size(), bottom_edges);
  const std::vector<RingCoordinate> ring = ring_coordinates(g);
  ASSERT_EQ(static_cast<int>(ring.size()), mesh.n_unwelded_vertices());
  for (int u = 0; u < mesh.n_unwelded_vertices(); ++u) {
    const double h = mesh.layout_positions_m[u].y();
    EXPECT_NEAR(ring[u].girth_m, shape.relaxed_girth_m(h), 1e-12);
    EXPECT_GE(ring[u].share, -1e-12);
    EXPECT_LE(ring[u].share, 1 + 1e-12);
  }
}

TEST(TaperedTube, RectangleTubeSharesAreTheLayoutOverTheCircumference) {
  const Garment g = make_tube_garment("T", 0.157, 0.24, 2, MeshSpacing{});
  const SimulationMesh mesh = weld(g);
  const std::vector<RingCoordinate> ring = ring_coordinates(g);
  for (int u = 0; u < mesh.n_unwelded_vertices(); ++u) {
    EXPECT_NEAR(ring[u].share, mesh.layout_positions_m[u].x() / 0.314, 1e-12);
    EXPECT_NEAR(ring[u].girth_m, 0.314, 1e-12);
  }
}

TEST(TaperedTube, BadShapesAreRefusedNamingTheEntry) {
  const auto message = [](const TaperedTubeShape& shape) {
    try {
      shape.validate();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  TaperedTubeShape s = stocking_like();
  s.girths_m = PiecewiseLinear({{0.0, 0.2}, {0.6, 0.3}}, "Girths");
  EXPECT_NE(message(s).find("Girths: height 0.6"), std::string::npos) << message(s);
  s = stocking_like();
  s.girths_m = PiecewiseLinear({{0.0, -0.2}}, "Girths");
  EXPECT_NE(message(s).find("must be positive"), std::string::npos) << message(s);
  s = stocking_like();
  s.negative_ease = PiecewiseLinear({{0.1, 1.0}}, "Negative ease");
  EXPECT_NE(message(s).find("Negative ease"), std::string::npos) << message(s);
  EXPECT_THROW(PiecewiseLinear({{0.2, 1.0}, {0.1, 2.0}}, "Girths"), std::invalid_argument);
  EXPECT_THROW(PiecewiseLinear({}, "Girths"), std::invalid_argument);
}

}  // namespace
}  // namespace tightfit
