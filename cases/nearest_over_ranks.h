// A nearest-point search over a surface shared out among the MPI ranks (MPI_COMM_WORLD): each
// rank searches a contiguous block of the surface's triangles, and for each query point the
// nearest of the ranks' answers is kept, so that no rank holds a search tree of the whole
// surface (about 265 bytes a triangle, docs/performance.md, "## MPI").
#pragma once

#include "core/types.h"

#include <array>
#include <utility>
#include <vector>

namespace tightfit {

// This rank among the ranks that share a search. The default, one rank, searches alone.
struct RankShare {
  int rank = 0;
  int n_ranks = 1;
  // This rank's block [first, end) of `n` triangles: n * rank / n_ranks onwards, so that the
  // blocks' sizes differ by one at most (empty when there are more ranks than triangles).
  std::pair<int, int> block(int n) const;
};

// What one rank's search found for one query point, and what the point reads there. Plain
// bytes, sent as such.
struct NearestReading {
  std::array<double, 3> query_m{};  // the query point
  std::array<double, 3> point_m{};  // the nearest point found
  int triangle = -1;                // its triangle among all the surface's; -1: none searched
  int flag = 0;                     // what the reading means is the caller's
  double value = 0.0;
};

// Replaces each query point's reading by the nearest over the ranks (collective): nearer by
// compare_distances (bodies/triangle_bvh.h), the exact comparison the search tree itself
// decides by, and between equally near points the lower triangle index, so that every rank
// keeps the same reading whatever the order of the ranks' answers. With one rank it returns.
void keep_nearest_over_ranks(std::vector<NearestReading>& readings, const RankShare& share);

}  // namespace tightfit
