// The garment's pattern as the finite-element reference domain: the panels' triangles laid out
// flat (one deal.II cell each, a seam being two edges), the vector-valued position field's
// degrees of freedom, the contact nodes and their copies across seams, and everything of the
// reference configuration that assembly reads at every Newton iteration (per cell: DoFs,
// quadrature weights, shape gradients in grain axes). Built once; read-only afterwards.
//
// No rank ever holds a triangulation of every cell: the triangles are partitioned once
// (pattern_partition.h), each rank builds a fully distributed triangulation of its own cells and
// one layer of ghosts round them, and deal.II numbers the garment's DoFs over the ranks. A node's
// copies across seams may lie on cells of ranks that share no cell: they are gathered by
// communication (node_copies_exchange.h). The triangulation and DoF handler only build the
// arrays below and are dropped once they are filled. The garment mesh itself need be whole on
// rank 0 only: the setup reads each rank's part of it, sent from there (mesh_part.h). Quadratic
// triangles still need the whole mesh on every rank: their welded edges (edge_ends,
// edge_index), each cell's corners (cell_vertices) and the surface's normals for the traction
// recovery are of the whole surface (docs/performance.md, MPI).
//
// Nodes: welded vertex w is node w; with degree 2, welded edge e's midpoint is node
// n_vertices + e. A node has one DoF triple per panel it lies in: the first carries it, the
// others follow it (seam constraints, fem_constraints.h).
//
// Each rank keeps the per-node arrays of its relevant nodes only (those of its own cells),
// numbered locally: local node k is global node global_node(k), ascending in k; on one rank the
// two numberings agree. Every per-node argument and array below is local unless it says
// "global" or "of every node".
#pragma once

#include "core/backend.h"
#include "core/compact_lists.h"
#include "core/constrained_directions.h"
#include "fem/cell_table.h"
#include "fem/mesh_part.h"
#include "fem/node_copies_exchange.h"

#include <deal.II/base/index_set.h>
#include <deal.II/base/partitioner.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <map>
#include <memory>
#include <vector>

namespace tightfit {

// The positions (and Newton increments) on this rank's DoFs and its ghosts, the other ranks' DoFs
// that its cells and nodes read (ReferenceMesh::relevant_dofs): x(i) reads or writes DoF i by its
// global number. Vector operations act on the owned entries and refresh the ghosts; a write to
// an owned entry by hand needs update_ghost_values() before another rank reads it.
using DofVector = dealii::LinearAlgebra::distributed::Vector<double>;

class ReferenceMesh {
 public:
  // Partitions the cells over `comm` (collective). problem.mesh and problem.constraints are read
  // on rank 0 only, and may be null and empty on the others with linear triangles; quadratic
  // ones need the mesh on every rank. Throws std::invalid_argument (on every rank) for a degree
  // other than 1 or 2, without a mesh on rank 0, or with degree 2 and a rank without one.
  ReferenceMesh(const Problem& problem, int element_degree, MPI_Comm communicator);

  GlobalDof n_dofs() const { return owned_dofs_.size(); }
  // The nodes of all ranks, and this rank's relevant ones.
  int n_nodes() const { return n_nodes_; }
  int n_local_nodes() const { return static_cast<int>(global_nodes_.size()); }
  // Local node -> its global number, and back (-1: not a node of this rank).
  int global_node(int node) const { return global_nodes_[node]; }
  int find_node(int global) const;
  int n_vertices() const { return n_vertices_; }
  // This rank's own cells (see cell_dofs), and the cells of all ranks.
  int n_cells() const { return cell_dofs_.size(); }
  int n_all_cells() const { return n_all_cells_; }
  int n_local_dofs() const { return static_cast<int>(fe_.n_dofs_per_cell()); }
  int n_element_nodes() const { return n_local_dofs() / 3; }
  // Copies own cell k's DoFs into `dofs` (deal.II's constraints take them as a vector).
  void get_cell_dofs(int k, std::vector<GlobalDof>& dofs) const {
    dofs.assign(cell_dofs_[k].begin(), cell_dofs_[k].end());
  }
  // Node-major index 3 a + c of a cell's local DoF i (node a, component c).
  int node_major(unsigned int i) const { return 3 * local_node_[i] + local_component_[i]; }

  // Local node `node`'s DoF triple of each copy (the first carries it), and the carrying one.
  ListView<DofTriple> copies(int node) const { return node_copies_[node]; }
  const DofTriple& carrier(int node) const { return node_copies_[node].front(); }
  // A local node's position in a DofVector (or another vector by global DoF).
  template <typename VectorType>
  Vec3 node_position(const VectorType& x, int node) const {
    const DofTriple& d = carrier(node);
    return Vec3(x(d[0]), x(d[1]), x(d[2]));
  }
  // Writes p into every copy of the local node (owned or ghost); the copies other ranks own
  // follow with copy_seams.
  void set_node_position(DofVector& x, int node, const Vec3& p) const;
  // After set_node_position on the owned nodes: every copy this rank owns takes the value of
  // the copy that carries its node, and the ghosts are refreshed (collective).
  void copy_seams(DofVector& x) const;
  // A zero vector over the relevant DoFs.
  DofVector dof_vector() const { return DofVector(partitioner_); }
  // The DoF vector of welded vertices at `positions_m`, each edge midpoint on its chord (every
  // rank is given every vertex, so it fills its ghosts itself).
  DofVector dof_positions(const std::vector<Vec3>& positions_m) const;
  // Per-node values of the owned nodes (in the order of owned_nodes) -> those of every node by
  // global number, on every rank (collective); T is double or Vec3.
  template <typename T>
  std::vector<T> gather_nodes(const std::vector<T>& owned_values) const;
  // Every welded vertex's position, on every rank (collective): for the output, which the case
  // driver reads whole on every rank.
  std::vector<Vec3> vertex_positions(const DofVector& x) const;

  // The whole mesh, with degree 2 only (null for degree 1: the setup reads the rank's part).
  const SimulationMesh* whole_mesh() const { return whole_mesh_; }
  int element_degree() const { return element_degree_; }
  MPI_Comm comm() const { return comm_; }
  const dealii::FESystem<2>& fe() const { return fe_; }
  const dealii::MappingFE<2>& mapping() const { return mapping_; }
  const dealii::QGaussSimplex<2>& quadrature() const { return quadrature_; }
  // This rank's DoFs (deal.II's numbering over the ranks' cells); its size() is the number of
  // DoFs of all ranks.
  const dealii::IndexSet& owned_dofs() const { return owned_dofs_; }
  // The owned DoFs and the ghosts: every DoF of the own cells (cell_dofs), and every copy of a
  // node one of them belongs to. What this rank reads of x and of an increment, and the
  // DoFs whose constraints it keeps.
  const dealii::IndexSet& relevant_dofs() const { return relevant_dofs_; }
  const std::shared_ptr<const dealii::Utilities::MPI::Partitioner>& partitioner() const {
    return partitioner_;
  }
  // The local nodes whose carrying copy's DoFs this rank owns, ascending (on one rank, every
  // node):
  // this rank assembles their contact and keeps their contact state (contact_nodes.h), each
  // node's at its position k in this list.
  const std::vector<int>& owned_nodes() const { return owned_nodes_; }
  int n_owned_nodes() const { return static_cast<int>(owned_nodes_.size()); }
  // Whether every node's DoF triple is three consecutive rows starting at a multiple of 3, and
  // every rank's DoFs whole triples (deal.II numbers a node's components together): the
  // matrix then has blocks of 3, one node each, as GAMG's rigid motions need.
  bool dofs_in_node_blocks() const { return dofs_in_node_blocks_; }
  // Local DoF i of a cell is component local_component[i] of element node local_node[i].
  const std::vector<int>& local_component() const { return local_component_; }
  const std::vector<int>& local_node() const { return local_node_; }

  // Degree 2, of every edge: welded edge -> its two welded vertices, and back from the sorted
  // pair (empty for degree 1).
  const std::vector<std::array<int, 2>>& edge_ends() const { return edge_ends_; }
  const std::map<std::array<int, 2>, int>& edge_index() const { return edge_index_; }
  // Rank 0's Problem::constraints (every rank's rigid-motion pins are chosen from them), and
  // them at each local node.
  const std::vector<VertexConstraint>& constraints() const { return constraints_; }
  const ConstrainedDirections& node_constrained() const { return node_constrained_; }
  // Degree 2, per cell of all ranks (by panel triangle): its corners' welded vertices in the
  // order of the cell's own (that of hat_values), for the traction recovery, which every rank
  // runs on the whole surface (empty for degree 1).
  const std::vector<std::array<int, 3>>& cell_vertices() const { return cell_vertices_; }

  // Per own cell k (the other ranks' cells that add to a row this rank owns, across the
  // partition's boundary or through a seam, are theirs to assemble: PETSc sends those entries,
  // and the sparsity pattern's rows are exchanged likewise, fem_constraints.cc).
  // cell_index[k] is the cell's panel triangle (mesh.triangles). Then its DoFs and per
  // quadrature point its JxW (layout area, m^2) and each element node's shape gradient in grain
  // axes (1/m), node-major [q * n_element_nodes + a]. They live on the reference (pattern)
  // configuration, so they are computed once. Each cell's arrays have one length, and are
  // stored in one block per kind (cell_table.h).
  const std::vector<int>& cell_index() const { return cell_index_; }
  const std::vector<Triangle>& cell_corners() const {
    return cell_corners_;
  }  // its welded vertices, in the triangle's order
  const CellTable<GlobalDof>& cell_dofs() const { return cell_dofs_; }
  const CellTable<double>& cell_JxW_m2() const { return cell_JxW_m2_; }
  const CellTable<Vec2>& cell_grad_grain() const { return cell_grad_grain_; }
  // Per cell, the ratio of grain to layout area; the linear hat of each cell corner at the
  // quadrature points [q][v].
  const std::vector<double>& cell_grain_area_ratio() const { return cell_grain_area_ratio_; }
  const std::vector<std::vector<double>>& hat_values() const { return hat_values_; }
  // The element's own (scalar) shape functions at the quadrature points [q][a], a the element
  // node of local_node.
  const std::vector<std::vector<double>>& shape_values() const { return shape_values_; }

  // Per cell and element node, int N_a dA over the cell's rest (grain) area, m^2: the node's
  // consistent share of the cell's area (sums to the cell's rest area), which carries the
  // fabric's weight.
  const CellTable<double>& cell_node_rest_area_m2() const { return cell_node_rest_area_m2_; }
  // The same summed over each node's cells of all ranks (a seam node's copies together), m^2:
  // of every node by global number, on every rank (collective).
  std::vector<double> node_rest_area_m2() const;

  // Mean rest edge length over the triangles' edges (an interior edge counted twice), m.
  double mean_edge_m() const { return mean_edge_m_; }
  // The whole mesh's mean_rest_edge_length_m and rest area (the stop rule's tension scale).
  double mean_rest_edge_m() const { return mean_rest_edge_m_; }
  double rest_area_m2() const { return rest_area_m2_; }
  // Per local node, its own rest edge length h_k (contact_nodes.h), m: it sets the node's
  // contact penalty and its force unit in Newton's stop rule.
  const std::vector<double>& node_edge_m() const { return node_edge_m_; }
  // Per local node, its positive rest area w_k for contact (add_nodal_rest_areas), m^2.
  const std::vector<double>& node_contact_area_m2() const { return node_contact_area_m2_; }

 private:
  // Filled by the constructor, read-only afterwards (the accessors above).
  const SimulationMesh* whole_mesh_ = nullptr;
  int element_degree_;
  MPI_Comm comm_;
  dealii::FESystem<2> fe_;
  dealii::MappingFE<2> mapping_;
  dealii::QGaussSimplex<2> quadrature_;
  dealii::IndexSet owned_dofs_;
  dealii::IndexSet relevant_dofs_;
  std::shared_ptr<const dealii::Utilities::MPI::Partitioner> partitioner_;
  std::vector<int> owned_nodes_;
  bool dofs_in_node_blocks_ = false;
  std::vector<int> local_component_;
  std::vector<int> local_node_;
  std::vector<std::array<int, 2>> edge_ends_;
  std::map<std::array<int, 2>, int> edge_index_;
  std::vector<VertexConstraint> constraints_;
  ConstrainedDirections node_constrained_;
  std::vector<std::array<int, 3>> cell_vertices_;
  std::vector<int> cell_index_;
  std::vector<Triangle> cell_corners_;
  CellTable<GlobalDof> cell_dofs_;
  CellTable<double> cell_JxW_m2_;
  CellTable<Vec2> cell_grad_grain_;
  std::vector<double> cell_grain_area_ratio_;
  std::vector<std::vector<double>> hat_values_;
  std::vector<std::vector<double>> shape_values_;
  CellTable<double> cell_node_rest_area_m2_;
  double mean_edge_m_ = 0.0;
  double mean_rest_edge_m_ = 0.0;
  double rest_area_m2_ = 0.0;
  std::vector<double> node_edge_m_;
  std::vector<double> node_contact_area_m2_;

  int n_vertices_ = 0;
  int n_nodes_ = 0;
  int n_all_cells_ = 0;
  std::vector<int> global_nodes_;  // local node -> global node, ascending
  CompactLists<DofTriple> node_copies_;
  std::vector<double> node_rest_area_m2_;  // per local node
  // The local nodes with a copy other than the carrying one among this rank's DoFs.
  std::vector<int> seam_nodes_;

  // Degree 2: numbers the welded edges (edge_ends, edge_index) in the order the triangles
  // meet them.
  void number_edges(const std::vector<Triangle>& welded_triangles);
  // The own cells' arrays (and their corners in cell_vertices); returns each of their element
  // nodes' copy and rest area share, for exchange_node_copies.
  std::vector<NodeCopy> build_cells(const dealii::DoFHandler<2>& dof_handler,
                                    const SimulationMeshPart& part);
  // node_edge_m and node_contact_area_m2: each rank's own cells' shares, summed over the ranks.
  void sum_node_lengths_and_areas(const SimulationMeshPart& part);
  // The local nodes, their copies and rest areas from exchange_node_copies; relevant_dofs, the
  // partitioner, owned_nodes and seam_nodes_.
  void keep_relevant_nodes(const std::vector<NodeCopy>& node_copies);
};

}  // namespace tightfit
