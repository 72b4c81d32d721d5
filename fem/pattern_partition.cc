#include "fem/pattern_partition.h"

#include <deal.II/base/mpi.h>
#include <deal.II/grid/cell_id.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <algorithm>
#include <array>
#include <unordered_map>
#include <utility>

namespace tightfit {

namespace {

// The graph of triangles sharing a welded edge (a seam's two sides joined): each welded edge's
// triangles, from the triangles' edges sorted by their ends.
dealii::SparsityPattern welded_edge_graph(const SimulationMesh& mesh) {
  const int n_triangles = static_cast<int>(mesh.triangles.size());
  std::vector<std::pair<std::array<int, 2>, int>> edges;
  edges.reserve(3 * mesh.triangles.size());
  for (int t = 0; t < n_triangles; ++t)
    for (int k = 0; k < 3; ++k) {
      std::array<int, 2> ends{mesh.triangles[t][k], mesh.triangles[t][(k + 1) % 3]};
      std::sort(ends.begin(), ends.end());
      edges.emplace_back(ends, t);
    }
  std::sort(edges.begin(), edges.end());
  dealii::DynamicSparsityPattern graph(n_triangles, n_triangles);
  for (std::size_t begin = 0, end = 0; begin < edges.size(); begin = end) {
    while (end < edges.size() && edges[end].first == edges[begin].first) ++end;
    for (std::size_t i = begin; i < end; ++i)
      for (std::size_t j = begin; j < end; ++j)
        if (i != j) graph.add(edges[i].second, edges[j].second);
  }
  dealii::SparsityPattern pattern;
  pattern.copy_from(graph);
  return pattern;
}

}  // namespace

std::vector<unsigned int> partition_triangles(const SimulationMesh& mesh, int n_ranks) {
  std::vector<unsigned int> partition(mesh.triangles.size(), 0);
  if (n_ranks > 1)
    dealii::SparsityTools::partition(welded_edge_graph(mesh), n_ranks, partition,
                                     dealii::SparsityTools::Partitioner::metis);
  return partition;
}

dealii::TriangulationDescription::Description<2, 2> own_cells_description(
    const SimulationMeshPart& part, MPI_Comm comm) {
  dealii::TriangulationDescription::Description<2, 2> description;
  description.comm = comm;
  description.settings = dealii::TriangulationDescription::Settings::default_setting;
  description.smoothing = dealii::Triangulation<2>::none;
  description.cell_infos.resize(1);
  // The own and ghost cells' vertices, numbered in the order they are met.
  std::unordered_map<int, unsigned int> local_vertex;
  for (const MeshPartTriangle& triangle : part.triangles) {
    dealii::CellData<2> cell(3);
    for (int k = 0; k < 3; ++k) {
      const auto [it, added] = local_vertex.emplace(
          triangle.unwelded[k], static_cast<unsigned int>(description.coarse_cell_vertices.size()));
      if (added) {
        const Vec2& x = triangle.layout_m[k];
        description.coarse_cell_vertices.emplace_back(x.x(), x.y());
      }
      cell.vertices[k] = it->second;
    }
    cell.material_id = triangle.panel;
    description.coarse_cells.push_back(cell);
    description.coarse_cell_index_to_coarse_cell_id.push_back(triangle.index);

    dealii::TriangulationDescription::CellData<2> info;
    info.id = dealii::CellId(triangle.index, {}).template to_binary<2>();
    info.subdomain_id = triangle.rank;
    info.level_subdomain_id = dealii::numbers::invalid_subdomain_id;  // no multigrid levels
    info.manifold_id = dealii::numbers::flat_manifold_id;
    info.manifold_line_ids.fill(dealii::numbers::flat_manifold_id);
    info.manifold_quad_ids.fill(dealii::numbers::flat_manifold_id);
    description.cell_infos[0].push_back(info);
  }
  return description;
}

}  // namespace tightfit
