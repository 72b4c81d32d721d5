#include "core/constrained_directions.h"
#include "core/closest_names.h"

#include <stdexcept>
#include <string>

namespace tightfit {

namespace {

// Directions closer than this to the span of those already held add nothing.
constexpr double independent = 1e-9;

// A vertex group of the mesh, or every vertex for the group "all".
std::vector<int> group_vertices(const SimulationMesh& mesh, const std::string& group) {
  if (group == "all") {
    std::vector<int> every(mesh.n_vertices);
    for (int v = 0; v < mesh.n_vertices; ++v) every[v] = v;
    return every;
  }
  const auto found = mesh.vertex_groups.find(group);
  if (found == mesh.vertex_groups.end()) {
    std::string known;
    std::vector<std::string> names{"all"};
    for (const auto& [name, vertices] : mesh.vertex_groups) {
      known += (known.empty() ? "" : ", ") + name;
      names.push_back(name);
    }
    throw std::invalid_argument("the garment has no vertex group '" + group + "' (it has: " +
                                known + ", and all)" + did_you_mean(group, names, 0));
  }
  return found->second;
}

}  // namespace

VertexConstraint held_along(const SimulationMesh& mesh, const std::string& group,
                            const Vec3& direction) {
  VertexConstraint c;
  c.kind = VertexConstraint::Kind::held_along_direction;
  c.group = group;
  c.vertices = group_vertices(mesh, group);
  c.direction = direction;
  return c;
}

VertexConstraint fixed_group(const SimulationMesh& mesh, const std::string& group) {
  VertexConstraint c;
  c.kind = VertexConstraint::Kind::fixed;
  c.group = group;
  c.vertices = group_vertices(mesh, group);
  return c;
}

namespace {

// Gram-Schmidt against the directions already held, so that removing components one after the
// other is a projection.
void add_direction(std::vector<Vec3>& held, const Vec3& direction) {
  Vec3 d = direction.normalized();
  for (const Vec3& h : held) d -= d.dot(h) * h;
  if (d.norm() > independent) held.push_back(d.normalized());
}

}  // namespace

ConstrainedDirections::ConstrainedDirections(const std::vector<VertexConstraint>& constraints,
                                             int n_vertices) {
  std::vector<std::vector<Vec3>> directions(n_vertices);
  for (const VertexConstraint& c : constraints) {
    const bool fixed = c.kind == VertexConstraint::Kind::fixed;
    if (!fixed && !(c.direction.norm() > 0))
      throw std::invalid_argument("constraint on vertex group '" + c.group +
                                  "': the held direction is zero");
    for (int v : c.vertices) {
      if (v < 0 || v >= n_vertices)
        throw std::invalid_argument("constraint on vertex group '" + c.group + "': vertex " +
                                    std::to_string(v) + " is not a vertex of the mesh");
      if (fixed)
        for (int axis = 0; axis < 3; ++axis) add_direction(directions[v], Vec3::Unit(axis));
      else
        add_direction(directions[v], c.direction);
    }
  }
  directions_ = CompactLists<Vec3>::from(directions);
}

ConstrainedDirections ConstrainedDirections::copies(const std::vector<int>& welded_index) const {
  ConstrainedDirections result;
  for (int w : welded_index) {
    if (w < 0 || w >= size())
      throw std::out_of_range("ConstrainedDirections::copies: no vertex " + std::to_string(w));
    result.directions_.push_back(directions_[w]);
  }
  result.directions_.shrink_to_fit();
  return result;
}

void ConstrainedDirections::add_shared(int a, int b) {
  std::vector<Vec3> shared;
  // A direction of a's that b holds too: its component outside b's span vanishes.
  for (const Vec3& d : directions_[a]) {
    Vec3 outside = d;
    for (const Vec3& e : directions_[b]) outside -= outside.dot(e) * e;
    if (outside.norm() < 1e-9) shared.push_back(d);
  }
  directions_.push_back(shared);
}

}  // namespace tightfit
