// Topology of a welded garment mesh for the pattern tests: edges used once (the boundary),
// edges used twice the same way round (inconsistent orientation), and the boundary's loops.
#pragma once

#include "core/garment.h"

#include <map>
#include <utility>
#include <vector>

namespace tightfit::pattern {

struct MeshTopology {
  int boundary_edges = 0;
  int misoriented_edges = 0;                     // an edge two triangles walk the same way
  int overused_edges = 0;                        // an edge of three or more triangles
  std::vector<std::vector<int>> boundary_loops;  // welded vertex indices round each loop
};

inline MeshTopology topology(const SimulationMesh& mesh) {
  std::map<std::pair<int, int>, int> directed;
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  MeshTopology result;
  std::map<int, int> next;  // boundary: a -> b for each directed edge without its opposite
  for (const auto& [edge, count] : directed) {
    const auto opposite = directed.find({edge.second, edge.first});
    const int opposite_count = opposite == directed.end() ? 0 : opposite->second;
    if (count > 1) ++result.misoriented_edges;
    if (count + opposite_count > 2) ++result.overused_edges;
    if (opposite_count == 0) {
      ++result.boundary_edges;
      next[edge.first] = edge.second;
    }
  }
  while (!next.empty()) {
    std::vector<int> loop{next.begin()->first};
    for (int v = next.begin()->second; v != loop.front();) {
      loop.push_back(v);
      const auto found = next.find(v);
      if (found == next.end()) break;
      const int after = found->second;
      next.erase(found);
      v = after;
    }
    next.erase(loop.front());
    result.boundary_loops.push_back(loop);
  }
  return result;
}

}  // namespace tightfit::pattern
