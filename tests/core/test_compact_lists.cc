// Packed lists of varying length: each list reads back as it was appended, empty lists
// included, and a copy of selected vertices' constrained directions keeps them per vertex.
#include "core/compact_lists.h"
#include "core/constrained_directions.h"
#include "core/tube_garment.h"

#include <gtest/gtest.h>

#include <vector>

namespace tightfit {
namespace {

TEST(CompactLists, ListsReadBackAsAppendedEmptyOnesIncluded) {
  const std::vector<std::vector<int>> lists{{}, {4}, {1, 2, 3}, {}, {7, 7}};
  const CompactLists<int> packed = CompactLists<int>::from(lists);
  ASSERT_EQ(packed.size(), 5);
  for (int k = 0; k < packed.size(); ++k) {
    const ListView<int> view = packed[k];
    EXPECT_EQ(std::vector<int>(view.begin(), view.end()), lists[k]) << "list " << k;
    EXPECT_EQ(view.size(), lists[k].size());
    EXPECT_EQ(view.empty(), lists[k].empty());
  }
  EXPECT_EQ(packed[2][1], 2);
  EXPECT_EQ(packed[4].front(), 7);
  EXPECT_EQ(CompactLists<int>().size(), 0);
}

TEST(CompactLists, CopiesOfConstrainedDirectionsFollowTheirVertices) {
  const SimulationMesh mesh = weld(make_tube_garment("T", 0.157, 0.24, 2, MeshSpacing{}));
  const ConstrainedDirections all(
      {held_along(mesh, "bottom", Vec3::UnitZ()), fixed_group(mesh, "top")}, mesh.n_vertices);
  // Every vertex in reverse order, then the first again.
  std::vector<int> picked;
  for (int v = mesh.n_vertices - 1; v >= 0; --v) picked.push_back(v);
  picked.push_back(0);
  const ConstrainedDirections copies = all.copies(picked);
  ASSERT_EQ(copies.size(), static_cast<int>(picked.size()));
  for (std::size_t k = 0; k < picked.size(); ++k) {
    const ListView<Vec3> expected = all.directions(picked[k]);
    const ListView<Vec3> got = copies.directions(static_cast<int>(k));
    ASSERT_EQ(got.size(), expected.size()) << "copy " << k;
    for (std::size_t d = 0; d < got.size(); ++d) EXPECT_EQ(got[d], expected[d]);
  }
  EXPECT_THROW(all.copies({mesh.n_vertices}), std::out_of_range);
}

}  // namespace
}  // namespace tightfit
