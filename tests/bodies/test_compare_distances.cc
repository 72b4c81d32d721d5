// compare_distances (bodies/triangle_bvh.h), by which the ranks' nearest points of their blocks
// of a surface are combined: exact where squared distances in double round alike, and the
// nearest over blocks of a random triangle soup is the point one search of the whole finds.
#include "bodies/triangle_bvh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace tightfit {
namespace {

TEST(CompareDistances, ExactWhereDoublesRoundAlike) {
  const Vec3 x(0, 0, 0);
  // |a|^2 = 1 + 1e-18 rounds to 1 = |b|^2 in double; a is the farther.
  const Vec3 a(1, 1e-9, 0), b(1, 0, 0);
  ASSERT_EQ(a.squaredNorm(), b.squaredNorm());
  EXPECT_EQ(compare_distances(x, a, b), 1);
  EXPECT_EQ(compare_distances(x, b, a), -1);
  EXPECT_EQ(compare_distances(x, b, Vec3(0, 0, -1)), 0);
  EXPECT_EQ(compare_distances(x, b, Vec3(std::nextafter(1.0, 2.0), 0, 0)), -1);
}

TEST(CompareDistances, NearestOverBlocksIsTheWholeSearchs) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> vertices(600);
  for (Vec3& v : vertices) v = Vec3(u(random), u(random), u(random));
  std::vector<Triangle> triangles;
  for (int t = 0; t < 200; ++t) triangles.push_back({3 * t, 3 * t + 1, 3 * t + 2});
  TriangleBvh whole;
  whole.build(vertices, triangles);
  // Three blocks of unequal size, as RankShare gives 200 triangles over 3 ranks.
  const int bounds[] = {0, 66, 133, 200};
  std::vector<TriangleBvh> blocks(3);
  for (int r = 0; r < 3; ++r)
    blocks[r].build(vertices, std::vector<Triangle>(triangles.begin() + bounds[r],
                                                    triangles.begin() + bounds[r + 1]));
  for (int q = 0; q < 2000; ++q) {
    const Vec3 x(2 * u(random), 2 * u(random), 2 * u(random));
    TriangleBvh::Hit best;
    for (int r = 0; r < 3; ++r) {
      TriangleBvh::Hit hit = blocks[r].closest(x);
      hit.triangle += bounds[r];
      if (best.triangle < 0 || compare_distances(x, hit.point_m, best.point_m) < 0) best = hit;
    }
    const TriangleBvh::Hit one = whole.closest(x);
    ASSERT_EQ(best.triangle, one.triangle) << "query " << q;
    ASSERT_EQ(best.point_m, one.point_m) << "query " << q;
  }
}

}  // namespace
}  // namespace tightfit
