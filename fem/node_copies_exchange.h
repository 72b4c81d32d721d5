// A node's copies across seams, gathered over the ranks. A welded vertex (or a seam edge's
// midpoint) has one DoF triple per panel it lies in, and the cells holding them may be on ranks
// that share no cell with each other: each rank knows only the copies its own cells hold. The
// copies are sent to the node's home rank (the nodes split in blocks over the ranks), which
// merges them and sends each node's whole list back to the ranks that hold one of its copies.
// No rank ever holds a list of every node.
#pragma once

#include <deal.II/base/types.h>

#include <mpi.h>

#include <array>
#include <vector>

namespace tightfit {

using GlobalDof = dealii::types::global_dof_index;
using DofTriple = std::array<GlobalDof, 3>;

// One copy of a node, as a rank's own cells see it.
struct NodeCopy {
  int node = 0;  // global node number
  // Orders a node's copies, the least carrying the node: the copy's unwelded vertex for a
  // vertex, the first panel triangle holding the edge for a midpoint.
  int order = 0;
  DofTriple dofs{};
  // Sent: this rank's cells' share of the node's rest area (m^2). Returned: the node's rest
  // area summed over every cell of every rank (all its copies).
  double rest_area_m2 = 0.0;

  // deal.II's packing sends vectors of these as bytes; it only names this fallback.
  template <class Archive>
  void serialize(Archive& archive, unsigned int) {
    archive& node& order& dofs[0] & dofs[1] & dofs[2] & rest_area_m2;
  }
};

// One record per copy (node and DoFs) of `copies`, sorted by node: the least order and the
// summed area of its repeats.
void merge_repeated_copies(std::vector<NodeCopy>& copies);

// Collective. `own`: a record per cell and element node of this rank's cells (repeats of a copy
// allowed; their shares are summed). Returns every copy of each node of `own`, nodes ascending,
// each node's copies in carrying order (least `order` first), each with the node's whole rest
// area. `n_nodes` is the number of nodes of all ranks.
std::vector<NodeCopy> exchange_node_copies(std::vector<NodeCopy> own, int n_nodes, MPI_Comm comm);

}  // namespace tightfit
