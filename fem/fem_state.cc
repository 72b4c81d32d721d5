#include "fem/fem_state.h"

#include "bodies/rigid_body.h"
#include "core/mesh_geometry.h"
#include "fem/traction_recovery.h"

#include <algorithm>

namespace tightfit {

namespace {

void fill_from_multipliers(const ReferenceMesh& pattern, const MembraneAssembly& assembly,
                           const RigidBody& body, const DofVector& x,
                           const std::vector<double>& multiplier_N,
                           const std::vector<Vec3>& friction_force_N, FemSurfaceOutput& out) {
  const int n = pattern.n_vertices();
  SurfaceState& state = out.state;
  state.internal_force_N = assembly.internal_force_N(x);
  state.contact_force_N.assign(n, Vec3::Zero());
  state.in_contact.assign(n, 0);
  state.gap_m.assign(n, 0.0);
  // Each vertex's barycentric area: each rank its own cells' thirds, summed over the ranks.
  std::vector<double> area =
      vertex_areas(pattern.cell_corners(), state.positions_m, n, VertexAreaDefinition::barycentric);
  MPI_Allreduce(MPI_IN_PLACE, area.data(), n, MPI_DOUBLE, MPI_SUM, pattern.comm());
  out.contact_traction_Pa.assign(n, 0.0);
  for (int w = 0; w < n; ++w) {
    const SurfacePoint s = body.query(state.positions_m[w]);
    state.gap_m[w] = s.signed_distance_m;
    if (multiplier_N[w] <= 0.0) continue;
    state.in_contact[w] = 1;
    state.contact_force_N[w] = multiplier_N[w] * s.outward_normal;
    if (!friction_force_N.empty()) state.contact_force_N[w] += friction_force_N[w];
    if (area[w] > 0.0) out.contact_traction_Pa[w] = multiplier_N[w] / area[w];
  }
}

// Quadratic elements carry a consistent load int N_k p dA at each node: about nothing at the
// corners and A/3 at the midpoints under a uniform pressure, so their nodal forces over
// vertex areas do not read a pressure. Worse, the corners' share is of either sign and
// contact cannot pull: on a cylinder the corners float a little off the body (by about h^4)
// and only the midpoints press. The traction is therefore recovered in the linear functions
// on the current (curved) surface, whose loads the nodal forces determine: the hat of vertex w
// is phi_w = N_w + 1/2 sum_e N_e over its edges e (a quadratic function), so int phi_w t dA =
// f_w + 1/2 sum_e f_e, and the L2 projection M t = f of traction_recovery.h (M_vw = int phi_v
// phi_w dA) returns the vertex tractions; it shares each midpoint's force between its edge's
// ends. Each welded vertex is then handed the force the shared extractor turns back into it:
//   internal_force_N = -(t A_v) n_v,  contact_force_N = t A_v n_body,
// with A_v the flat barycentric area and n_v the vertex normal the extractor computes
// (oriented away from the body), so that p_v = -(f . n_v) / A_v = t exactly, and a uniform
// pressure reads its value at every vertex.
//
// Under gravity the garment's own force is not the contact force: at each node it balances the
// contact force and the weight f_g, so its normal load is lambda + f_g . n_body (the weight
// lessens it where it presses, n_body . g < 0). That load is recovered as a second traction
// t_g and the internal force becomes -(t_g A_v) n_v.
//
// With friction the nodal tangential forces are consistent loads too: each Cartesian component
// is recovered the same way, and each vertex gets the recovered friction traction's part
// tangent to the body there times A_v in its contact force (the extractor's friction traction).
void fill_from_recovered_traction(const ReferenceMesh& pattern, const RigidBody& body,
                                  const DofVector& x, const std::vector<double>& multiplier_N,
                                  const std::vector<Vec3>& gravity_load_N,
                                  const std::vector<Vec3>& friction_force_N,
                                  FemSurfaceOutput& out) {
  const SimulationMesh& mesh = *pattern.whole_mesh();  // degree 2: on every rank
  const int n = mesh.n_vertices;
  SurfaceQuadrature quadrature;
  quadrature.shape_values = pattern.hat_values();
  for (const auto& v : pattern.cell_vertices())
    quadrature.cell_nodes.emplace_back(v.begin(), v.end());
  const unsigned int n_local = pattern.n_local_dofs();
  const unsigned int n_element_nodes = pattern.n_element_nodes();
  const std::size_t n_points = pattern.quadrature().size();
  // Each rank its own cells' points, summed over the ranks: every rank recovers all of it.
  std::vector<double> point_area_m2(pattern.n_all_cells() * n_points, 0.0);
  for (int cell = 0; cell < pattern.n_cells(); ++cell) {
    for (unsigned int q = 0; q < n_points; ++q) {
      // dA = |x,1 x x,2| dA_grain, x,i the columns of F = dx/dX_grain.
      Mat32 F = Mat32::Zero();
      for (unsigned int i = 0; i < n_local; ++i)
        F.row(pattern.local_component()[i]) +=
            x(pattern.cell_dofs()[cell][i]) *
            pattern.cell_grad_grain()[cell][q * n_element_nodes + pattern.local_node()[i]]
                .transpose();
      const double grain_area_m2 =
          pattern.cell_JxW_m2()[cell][q] * pattern.cell_grain_area_ratio()[cell];
      point_area_m2[pattern.cell_index()[cell] * n_points + q] =
          Vec3(F.col(0)).cross(Vec3(F.col(1))).norm() * grain_area_m2;
    }
  }
  MPI_Allreduce(MPI_IN_PLACE, point_area_m2.data(), static_cast<int>(point_area_m2.size()),
                MPI_DOUBLE, MPI_SUM, pattern.comm());
  quadrature.point_area_m2.resize(pattern.n_all_cells());
  for (int cell = 0; cell < pattern.n_all_cells(); ++cell)
    quadrature.point_area_m2[cell].assign(point_area_m2.begin() + cell * n_points,
                                          point_area_m2.begin() + (cell + 1) * n_points);
  const auto& edge_ends = pattern.edge_ends();
  // The loads against the vertex hats of nodal normal loads (a midpoint's to its edge's ends).
  const auto hat_loads = [&](const std::vector<double>& node_load_N) {
    std::vector<double> hat_load_N(n, 0.0);
    for (int w = 0; w < n; ++w) hat_load_N[w] = node_load_N[w];
    for (std::size_t e = 0; e < edge_ends.size(); ++e)
      for (int w : edge_ends[e]) hat_load_N[w] += 0.5 * node_load_N[n + e];
    return hat_load_N;
  };
  std::vector<double> contact_load_N(multiplier_N.size());
  for (std::size_t k = 0; k < multiplier_N.size(); ++k)
    contact_load_N[k] = std::max(0.0, multiplier_N[k]);
  const std::vector<double> traction =
      recover_traction_Pa(n, quadrature, hat_loads(contact_load_N));
  std::vector<double> garment_traction = traction;
  if (!gravity_load_N.empty()) {
    // The weight's normal part at each owned node, then at every node.
    std::vector<double> owned_weight_N;
    for (const int node : pattern.owned_nodes())
      owned_weight_N.push_back(gravity_load_N[pattern.global_node(node)].dot(
          body.query(pattern.node_position(x, node)).outward_normal));
    const std::vector<double> weight_N = pattern.gather_nodes(owned_weight_N);
    std::vector<double> garment_load_N = contact_load_N;
    for (int k = 0; k < pattern.n_nodes(); ++k) garment_load_N[k] += weight_N[k];
    garment_traction = recover_traction_Pa(n, quadrature, hat_loads(garment_load_N));
  }
  // Frictionless, the tangential forces are all zero: nothing to recover.
  std::vector<Vec3> friction_traction_Pa;
  if (std::any_of(friction_force_N.begin(), friction_force_N.end(),
                  [](const Vec3& f) { return f != Vec3::Zero(); })) {
    friction_traction_Pa.assign(n, Vec3::Zero());
    std::vector<double> component_N(friction_force_N.size());
    for (int c = 0; c < 3; ++c) {
      for (std::size_t k = 0; k < friction_force_N.size(); ++k)
        component_N[k] = friction_force_N[k][c];
      const std::vector<double> t = recover_traction_Pa(n, quadrature, hat_loads(component_N));
      for (int w = 0; w < n; ++w) friction_traction_Pa[w][c] = t[w];
    }
  }

  // A vertex touches the body where its own node or a midpoint of one of its edges does.
  std::vector<char> touching(n, 0);
  for (int w = 0; w < n; ++w) touching[w] = multiplier_N[w] > 0.0;
  for (std::size_t e = 0; e < edge_ends.size(); ++e)
    if (multiplier_N[n + e] > 0.0) touching[edge_ends[e][0]] = touching[edge_ends[e][1]] = 1;

  SurfaceState& state = out.state;
  const std::vector<double> area =
      vertex_areas(mesh.triangles, state.positions_m, n, VertexAreaDefinition::barycentric);
  const std::vector<Vec3> normal = vertex_normals(mesh.triangles, state.positions_m, n);
  state.internal_force_N.assign(n, Vec3::Zero());
  state.contact_force_N.assign(n, Vec3::Zero());
  state.in_contact.assign(n, 0);
  state.gap_m.assign(n, 0.0);
  out.contact_traction_Pa.assign(n, 0.0);
  for (int w = 0; w < n; ++w) {
    const SurfacePoint s = body.query(state.positions_m[w]);
    state.gap_m[w] = s.signed_distance_m;
    if (!touching[w]) continue;
    const Vec3 n_v = normal[w].dot(s.outward_normal) < 0.0 ? Vec3(-normal[w]) : normal[w];
    state.in_contact[w] = 1;
    out.contact_traction_Pa[w] = traction[w];
    state.internal_force_N[w] = -(garment_traction[w] * area[w]) * n_v;
    state.contact_force_N[w] = traction[w] * area[w] * s.outward_normal;
    if (!friction_traction_Pa.empty()) {
      const Vec3& t = friction_traction_Pa[w];
      state.contact_force_N[w] += area[w] * (t - t.dot(s.outward_normal) * s.outward_normal);
    }
  }
}

}  // namespace

FemSurfaceOutput surface_output(const ReferenceMesh& pattern, const MembraneAssembly& assembly,
                                const RigidBody& body, const DofVector& x,
                                const std::vector<double>& multiplier_N,
                                const std::vector<Vec3>& gravity_load_N,
                                const std::vector<Vec3>& friction_force_N) {
  FemSurfaceOutput out;
  out.state.positions_m = pattern.vertex_positions(x);
  if (pattern.element_degree() == 1)
    fill_from_multipliers(pattern, assembly, body, x, multiplier_N, friction_force_N, out);
  else
    fill_from_recovered_traction(pattern, body, x, multiplier_N, gravity_load_N, friction_force_N,
                                 out);
  return out;
}

OwnedSurfaceOutput::OwnedSurfaceOutput(const ReferenceMesh& pattern, const FemSurfaceOutput& whole)
    : has_step_(true) {
  const SurfaceState& state = whole.state;
  for (const int node : pattern.owned_nodes()) {
    const int w = pattern.global_node(node);
    const bool vertex = w < pattern.n_vertices();
    positions_m_.push_back(vertex ? state.positions_m[w] : Vec3::Zero());
    internal_force_N_.push_back(vertex ? state.internal_force_N[w] : Vec3::Zero());
    contact_force_N_.push_back(vertex ? state.contact_force_N[w] : Vec3::Zero());
    gap_m_.push_back(vertex ? state.gap_m[w] : 0.0);
    in_contact_.push_back(vertex && state.in_contact[w] ? 1.0 : 0.0);
    contact_traction_Pa_.push_back(vertex ? whole.contact_traction_Pa[w] : 0.0);
  }
}

namespace {

// Every vertex's values from the owned nodes' (collective): the vertices come first.
template <typename T>
std::vector<T> every_vertex(const ReferenceMesh& pattern, const std::vector<T>& owned_values) {
  std::vector<T> values = pattern.gather_nodes(owned_values);
  values.resize(pattern.n_vertices());
  return values;
}

}  // namespace

SurfaceState OwnedSurfaceOutput::state(const ReferenceMesh& pattern) const {
  SurfaceState state;
  if (!has_step_) return state;
  state.positions_m = every_vertex(pattern, positions_m_);
  state.internal_force_N = every_vertex(pattern, internal_force_N_);
  state.contact_force_N = every_vertex(pattern, contact_force_N_);
  state.gap_m = every_vertex(pattern, gap_m_);
  const std::vector<double> in_contact = every_vertex(pattern, in_contact_);
  state.in_contact.reserve(in_contact.size());
  for (const double c : in_contact) state.in_contact.push_back(c > 0.5);
  return state;
}

std::vector<double> OwnedSurfaceOutput::contact_traction_Pa(const ReferenceMesh& pattern) const {
  return has_step_ ? every_vertex(pattern, contact_traction_Pa_) : std::vector<double>{};
}

}  // namespace tightfit
