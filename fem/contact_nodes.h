// The augmented-Lagrangian contact's state at the FE nodes (welded vertices, then with degree 2
// the welded edges' midpoints): each node's penalty stiffness and multiplier estimate, the
// arguments of contact/nodal_contact.h, and each node's own mesh size h_k, which sets its
// penalty and its share of Newton's stop rule.
#pragma once

#include "contact/friction_anchors.h"
#include "core/garment.h"

#include <array>
#include <map>
#include <vector>

namespace tightfit {

// The branch of the Coulomb cone a Newton step is solved on at a node: its own at the point
// assembled, sticking, or slipping along a direction the prediction fixes.
enum class FrictionBranch : signed char { own, stick, slip };

struct PredictedSide {
  signed char contact = 0;  // 0 the node's own at x, +1 in contact, -1 out of contact
  FrictionBranch friction = FrictionBranch::own;
  Vec3 slip_direction = Vec3::Zero();  // unit, tangential, for FrictionBranch::slip
  // Same sides of both kinks (the slip direction follows from them).
  bool same_branches(const PredictedSide& other) const {
    return contact == other.contact && friction == other.friction;
  }
};

// Each array holds this rank's nodes only, node ReferenceMesh::owned_nodes[k] at position k (on
// one rank, every node at its own number): the rank that owns a node's DoFs assembles its contact.
struct ContactNodes {
  std::vector<double> penalty_N_per_m;  // k_k w_k per node (w_k its positive nodal rest area)
  std::vector<double> multiplier_N;     // augmented-Lagrangian estimate per node, N
  // Coulomb friction's anchors per node, the tangential penalty of node k being the Problem's
  // tangential stiffness times w_k (inactive when the Problem's mu is 0).
  FrictionAnchors friction;
  // Per owned node, the side of the contact and friction kinks a Newton step is solved on
  // (contact_set_prediction.h). Empty: every node its own at the point assembled.
  std::vector<PredictedSide> predicted;
  // Per owned node, the body's memory of its last query (RigidBody::query_near): a Newton
  // iterate moves a node little, and a mesh body then searches only the few faces kept near it
  // instead of its whole tree, with the tree's own answer. Only a cache, hence mutable.
  mutable std::vector<NearFaces> near_faces;

  // body.query(p) for the node at position k, through its kept faces once near_faces is sized.
  SurfacePoint query(const RigidBody& body, int k, const Vec3& p) const {
    return near_faces.empty() ? body.query(p) : body.query_near(p, near_faces[k]);
  }
  NearFaces* near(int k) const { return near_faces.empty() ? nullptr : &near_faces[k]; }
};

// The rest edge length h_k of each node, m. A vertex: the mean rest length of the triangle
// edges that meet at it (each triangle counts its two edges there, so on a uniform mesh every
// interior vertex gets the mesh's mean edge). A midpoint (degree 2): the mean of its edge's two
// ends. On a graded mesh h_k follows the local element size, where one mean edge would make
// the small elements' nodes soft (slow multiplier updates) and the large ones' stiff.
// `edge_ends` maps a welded edge to its two welded vertices (empty for degree 1).
std::vector<double> node_edge_lengths_m(const SimulationMesh& mesh,
                                        const std::vector<std::array<int, 2>>& edge_ends,
                                        int element_degree);
// The same in two halves, for triangles spread over ranks: each triangle (welded corners `v`,
// rest corners `rest_m`) adds its edges to its vertices' sums of lengths and counts; from the
// sums over every triangle, each node's h_k.
void add_node_edge_lengths(const Triangle& v, const std::array<Vec2, 3>& rest_m,
                           std::vector<double>& length_sum_m, std::vector<double>& count);
std::vector<double> node_edge_lengths_m(const std::vector<double>& length_sum_m,
                                        const std::vector<double>& count,
                                        const std::vector<std::array<int, 2>>& edge_ends,
                                        int element_degree);

// The positive rest area w_k of each node, m^2. Linear triangles (degree 1): the barycentric
// third of each triangle (their lumped mass, the mass-spring backend's vertex area). Quadratic
// triangles: their lumped (row-sum) mass gives the corners zero area, which would leave them
// without contact, so each triangle is split at its edge midpoints into four linear triangles of
// area A/4 whose lumped masses give A/12 to each corner and A/4 to each midpoint (3 x A/12 + 3 x
// A/4 = A). `edge_index` maps a sorted welded vertex pair to its edge's midpoint node minus
// n_vertices. Each triangle (welded corners `v`, rest area `area_m2`) adds its shares to
// `area_m2_of_node` (of every node: n_vertices, then the midpoints); summed over every triangle
// (over the ranks, each its own), they are the w_k.
void add_nodal_rest_areas(const Triangle& v, double area_m2, int n_vertices,
                          const std::map<std::array<int, 2>, int>& edge_index, int element_degree,
                          std::vector<double>& area_m2_of_node);

// The penalty k_k w_k of each node, with k_k = beta Y / h_k^2 (Pa/m; beta_Y_N_per_m = beta Y).
// It only sets how fast the augmented-Lagrangian updates converge, never the converged state.
std::vector<double> nodal_penalties_N_per_m(const std::vector<double>& node_rest_area_m2,
                                            double beta_Y_N_per_m,
                                            const std::vector<double>& node_edge_m);

}  // namespace tightfit
