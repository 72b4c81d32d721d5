// Lumped particle masses carry exactly the fabric's mass; the mean rest edge length (the
// length scale of the stop rule and of the penalty) in closed form.
#include "core/material.h"
#include "core/tube_garment.h"
#include "massspring/lumped_mass.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

namespace tightfit {
namespace {

TEST(LumpedMass, SumsToArealDensityTimesGarmentArea) {
  const double density = FabricParameters{}.areal_density_kg_per_m2;
  for (const auto& [width, spacing] :
       {std::pair{0.1878, MeshSpacing{}}, std::pair{0.157, MeshSpacing{0.004, 0.011}}}) {
    const SimulationMesh tube = weld(make_tube_garment("tube", width, 0.24, 2, spacing));
    const auto masses = lumped_masses_kg(tube, density);
    ASSERT_EQ(static_cast<int>(masses.size()), tube.n_vertices);
    const double total = std::accumulate(masses.begin(), masses.end(), 0.0);
    // Two panels of width x 0.24 m, from the garment's dimensions, not from the mesh.
    EXPECT_NEAR(total, density * 2 * width * 0.24, 1e-12);
    for (double m : masses) EXPECT_GT(m, 0.0);
  }
}

TEST(LumpedMass, MeanRestEdgeLengthOfAGridInClosedForm) {
  // A 0.3 x 0.2 m panel of 3 x 4 cells of 0.1 x 0.05 m, each cut by one diagonal
  // (core/rectangle_panel.h): 3 x 5 edges of 0.1 m along x, 4 x 4 of 0.05 m along y and 12
  // diagonals of sqrt(0.1^2 + 0.05^2) m, 43 edges in all.
  const SimulationMesh mesh = test::panel_mesh(0.3, 0.2, MeshSpacing{0.1, 0.05});
  const double expected = (15 * 0.1 + 16 * 0.05 + 12 * std::hypot(0.1, 0.05)) / 43;
  EXPECT_NEAR(mean_rest_edge_length_m(mesh), expected, 1e-15);
}

}  // namespace
}  // namespace tightfit
