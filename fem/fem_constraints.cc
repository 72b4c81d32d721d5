#include "fem/fem_constraints.h"

#include "core/held_turn.h"
#include "fem/freed_memory.h"
#include "fem/rigid_motion_pin.h"

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <cmath>
#include <utility>

namespace tightfit {

namespace {

// Adds homogeneous constraints dx . d = 0 for each direction d on one vertex's three DoFs.
// Each direction eliminates one component, chosen after removing the components the earlier
// directions eliminated, so the constraints never form a cycle.
template <typename Directions>
void constrain_directions(const DofTriple& dofs, const Directions& directions,
                          dealii::AffineConstraints<double>& constraints) {
  std::array<bool, 3> eliminated{false, false, false};
  std::vector<std::pair<int, Vec3>> done;
  for (Vec3 d : directions) {
    for (const auto& [component, previous] : done)
      d -= (d[component] / previous[component]) * previous;
    int pivot = -1;
    for (int c = 0; c < 3; ++c)
      if (!eliminated[c] && (pivot < 0 || std::abs(d[c]) > std::abs(d[pivot]))) pivot = c;
    if (pivot < 0 || std::abs(d[pivot]) < 1e-12) continue;  // already implied
    eliminated[pivot] = true;
    done.emplace_back(pivot, d);
    if (constraints.is_constrained(dofs[pivot])) continue;
    constraints.add_line(dofs[pivot]);
    for (int c = 0; c < 3; ++c)
      if (c != pivot && d[c] != 0.0) constraints.add_entry(dofs[pivot], dofs[c], -d[c] / d[pivot]);
  }
}

}  // namespace

void build_constraints_and_system(const ReferenceMesh& pattern, const Problem& problem,
                                  const std::vector<Vec3>& positions_m, MPI_Comm comm,
                                  NewtonSystem& system) {
  dealii::AffineConstraints<double>& constraints = system.constraints;
  // Only the constraints of this rank's relevant DoFs: its cells' DoFs and their nodes' copies
  // (a node's copies are relevant together, so a seam or a direction never reaches a DoF the
  // rank does not keep). Assembly, the sparsity pattern and distributing an increment read no
  // others.
  const dealii::IndexSet& relevant = pattern.relevant_dofs();
  constraints.clear();
  constraints.reinit(relevant);
  // Seams: every copy of a node (a welded vertex, or the midpoint of a seam edge) follows
  // the copy that carries it. Every copy of this rank's nodes is relevant here.
  for (int node = 0; node < pattern.n_local_nodes(); ++node) {
    const ListView<DofTriple> copies = pattern.copies(node);
    for (std::size_t k = 1; k < copies.size(); ++k)
      for (int c = 0; c < 3; ++c) {
        constraints.add_line(copies[k][c]);
        constraints.add_entry(copies[k][c], copies[0][c], 1.0);
      }
  }
  // Constrained nodes keep their coordinates along their constrained directions.
  for (int node = 0; node < pattern.n_local_nodes(); ++node)
    if (pattern.node_constrained().constrained(node))
      constrain_directions(pattern.carrier(node), pattern.node_constrained().directions(node),
                           constraints);
  // The pins are chosen among every vertex alike on every rank: from the whole garment's
  // positions and rank 0's constraints (held only while they are chosen).
  // The turn about the held direction, when every vertex is held along it, is held by the
  // bordered Newton system instead (held_turn_system.h).
  const HeldTurn held_turn(pattern.constraints(), pattern.n_vertices());
  const RigidMotionPin pin = rigid_motion_pin(
      *problem.body, positions_m,
      ConstrainedDirections(pattern.constraints(), pattern.n_vertices()),
      problem.friction_coefficient > 0.0, held_turn.active() ? &held_turn.axis() : nullptr);
  for (const RigidMotionPin::Pin& p : pin.pins) {
    const int node = pattern.find_node(p.vertex);
    if (node >= 0) constrain_directions(pattern.carrier(node), p.directions, constraints);
  }
  constraints.close();

  // Each rank adds its own cells' entries, in its relevant rows (a seam copy's go to the row
  // of the copy that carries its node), and sends those of other ranks' rows to their owners:
  // each then stores only its own rows.
  {
    dealii::DynamicSparsityPattern sparsity(pattern.n_dofs(), pattern.n_dofs(), relevant);
    std::vector<GlobalDof> dofs;
    for (int cell = 0; cell < pattern.n_cells(); ++cell) {
      pattern.get_cell_dofs(cell, dofs);
      constraints.add_entries_local_to_global(dofs, sparsity, false);
    }
    dealii::SparsityTools::distribute_sparsity_pattern(sparsity, pattern.owned_dofs(), comm,
                                                       relevant);
    system.tangent.reinit(pattern.owned_dofs(), pattern.owned_dofs(), sparsity, comm);
  }
  release_freed_memory();
  system.rhs.reinit(pattern.owned_dofs(), comm);
  system.increment.reinit(pattern.owned_dofs(), comm);
}

}  // namespace tightfit
