// Lumped particle masses carry exactly the fabric's mass.
#include "core/material.h"
#include "core/tube_garment.h"
#include "massspring/lumped_mass.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <numeric>
#include <set>

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

TEST(LumpedMass, MeanRestEdgeLengthOfARegularStrip) {
  // One 2 x 1 rectangle of spacing 1 x 1: rows y = 0 (3 vertices) and y = 1 (shifted: x = 0,
  // 0.5, 1.5, 2), edges: 2 + 3 along the rows, then the zipped diagonals.
  const SimulationMesh mesh = test::panel_mesh(2.0, 1.0, MeshSpacing{1.0, 1.0});
  std::set<std::pair<int, int>> edges;
  double sum = 0.0;
  for (std::size_t k = 0; k < mesh.triangles.size(); ++k)
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      if (edges.insert(std::minmax(mesh.triangles[k][i], mesh.triangles[k][j])).second)
        sum += (mesh.layout_positions_m[mesh.triangles[k][j]] -
                mesh.layout_positions_m[mesh.triangles[k][i]])
                   .norm();
    }
  EXPECT_NEAR(mean_rest_edge_length_m(mesh), sum / edges.size(), 1e-14);
}

}  // namespace
}  // namespace tightfit
