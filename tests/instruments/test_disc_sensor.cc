// The air-pack sensor's disc integral on a flat sheet, against closed forms: the mean of a
// linear pressure field over a disc is its value at the centre; the disc's area is pi d^2 / 4.
#include "core/garment.h"
#include "core/rectangle_panel.h"
#include "core/units.h"
#include "instruments/disc_sensor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace tightfit {
namespace {

struct FlatSheet {
  SimulationMesh mesh;
  std::vector<Vec3> positions;
  FlatSheet() {
    Garment g;
    g.panels.push_back(make_rectangle_panel("sheet", 0.1, 0.1, MeshSpacing{0.008, 0.011}));
    mesh = weld(g);
    positions.resize(mesh.n_vertices);
    for (int u = 0; u < mesh.n_unwelded_vertices(); ++u) {
      const Vec2 X = mesh.layout_positions_m[u];
      positions[mesh.welded_index[u]] = Vec3(X.x(), X.y(), 0.0);
    }
  }
  // p = 500 + 2e4 x - 1e4 y Pa at every vertex.
  std::vector<double> linear_field() const {
    std::vector<double> p;
    for (const Vec3& x : positions) p.push_back(500.0 + 2e4 * x.x() - 1e4 * x.y());
    return p;
  }
};

TEST(DiscSensor, ReadsALinearFieldAtItsCentre) {
  const FlatSheet sheet;
  const AirPackSpecification table1;
  for (const Vec3& centre : {Vec3(0.05, 0.05, 0.0), Vec3(0.031, 0.062, 0.0)}) {
    const DiscReading r = read_disc(sheet.positions, sheet.mesh.triangles, sheet.linear_field(),
                                    centre, Vec3::UnitZ(), table1);
    const double expected = 500.0 + 2e4 * centre.x() - 1e4 * centre.y();
    std::printf("disc at (%.3f, %.3f): reading %+.2e relative, area %+.2e relative\n", centre.x(),
                centre.y(), r.pressure_Pa / expected - 1.0,
                r.covered_area_m2 / (M_PI * 0.0075 * 0.0075) - 1.0);
    // The field varies by +/- 20% across the disc; the sub-triangles cut at a twentieth of the
    // diameter leave measured errors up to 3.9e-4 of the reading; tolerance 1e-3.
    EXPECT_NEAR(r.pressure_Pa, expected, 1e-3 * expected);
    // Area: measured -0.19% and +0.015% of pi d^2 / 4 (the cut goes either way); 0.3%.
    EXPECT_NEAR(r.covered_area_m2 / (M_PI * 0.0075 * 0.0075), 1.0, 0.003);
    EXPECT_NEAR(r.force_N, r.pressure_Pa * M_PI * 0.0075 * 0.0075, 1e-12);
    EXPECT_TRUE(r.in_range);
    EXPECT_GT(r.n_triangles, 4);
  }
}

TEST(DiscSensor, ClipsItsDisplayToTheInstrumentsRange) {
  const FlatSheet sheet;
  const AirPackSpecification table1;
  const std::vector<double> high(sheet.positions.size(), 80.0 * units::pascal_per_gf_per_cm2);
  const DiscReading r = read_disc(sheet.positions, sheet.mesh.triangles, high, Vec3(0.05, 0.05, 0),
                                  Vec3::UnitZ(), table1);
  EXPECT_NEAR(r.pressure_Pa, 80.0 * units::pascal_per_gf_per_cm2, 1e-9);
  EXPECT_FALSE(r.in_range);
  EXPECT_DOUBLE_EQ(r.displayed_Pa, 70.0 * units::pascal_per_gf_per_cm2);
}

TEST(DiscSensor, OffTheGarmentItReadsNothing) {
  const FlatSheet sheet;
  const DiscReading r = read_disc(sheet.positions, sheet.mesh.triangles, sheet.linear_field(),
                                  Vec3(0.5, 0.5, 0), Vec3::UnitZ(), AirPackSpecification{});
  EXPECT_EQ(r.n_triangles, 0);
  EXPECT_EQ(r.covered_area_m2, 0.0);
  EXPECT_EQ(r.pressure_Pa, 0.0);
}

}  // namespace
}  // namespace tightfit
