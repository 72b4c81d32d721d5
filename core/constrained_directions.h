// Per-vertex view of a Problem's constraints (core/backend.h), as both backends apply them: at
// each constrained vertex an orthonormal set of directions along which it may not move (one
// for a vertex held along a direction, three for a fixed one). The backends remove these
// components from forces, velocities and Newton increments.
#pragma once

#include "core/backend.h"
#include "core/compact_lists.h"

#include <string>
#include <vector>

namespace tightfit {

// The constraint on the mesh's vertex group `group`: held along `direction`, or fixed. Throws
// std::invalid_argument naming the group and the groups the mesh has when it has no such group.
VertexConstraint held_along(const SimulationMesh& mesh, const std::string& group,
                            const Vec3& direction);
VertexConstraint fixed_group(const SimulationMesh& mesh, const std::string& group);

class ConstrainedDirections {
 public:
  ConstrainedDirections() = default;
  // Throws std::invalid_argument naming the constraint's group when a vertex is not one of the
  // mesh's `n_vertices` or a held direction is zero.
  ConstrainedDirections(const std::vector<VertexConstraint>& constraints, int n_vertices);
  // The same constraints on copies of the vertices: copy c is vertex welded_index[c] (the
  // unwelded panels of the flat-panel start, or a node list of which the vertices come first).
  ConstrainedDirections copies(const std::vector<int>& welded_index) const;

  int size() const { return directions_.size(); }
  bool constrained(int v) const { return !directions_[v].empty(); }
  ListView<Vec3> directions(int v) const { return directions_[v]; }
  // Removes from `vector` its components along vertex v's constrained directions.
  void remove_constrained(int v, Vec3& vector) const {
    for (const Vec3& d : directions_[v]) vector -= vector.dot(d) * d;
  }
  // Appends a vertex with the directions both `a` and `b` constrain (an edge midpoint of
  // quadratic elements, constrained where both its ends are).
  void add_shared(int a, int b);

 private:
  // Stored packed (compact_lists.h): most vertices have none.
  CompactLists<Vec3> directions_;
};

}  // namespace tightfit
