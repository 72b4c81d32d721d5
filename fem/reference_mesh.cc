#include "fem/reference_mesh.h"

#include "fem/contact_nodes.h"
#include "fem/freed_memory.h"
#include "fem/pattern_partition.h"

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/reference_cell.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace tightfit {

namespace {

// Points per direction of the simplex Gauss rule for each element degree. Degree 1: one point
// integrates the constant strain of a linear triangle exactly (the mass-spring element).
// Degree 2: 7 points, exact to polynomial degree 5, so that the membrane energy (C quadratic
// in the linear gradients, S(C) smooth) does not lose the element's h^4; the traction
// recovery's mass matrix (products of linear hats times the area ratio) uses it too.
unsigned int gauss_points_1d(int element_degree) {
  if (element_degree == 1) return 1;
  if (element_degree == 2) return 3;
  throw std::invalid_argument("fem backend: Element degree must be 1 or 2, not " +
                              std::to_string(element_degree));
}

}  // namespace

ReferenceMesh::ReferenceMesh(const Problem& problem, int degree, MPI_Comm communicator)
    : element_degree_(degree),
      comm_(communicator),
      fe_(dealii::FE_SimplexP<2>(degree), 3),
      mapping_(dealii::FE_SimplexP<2>(1)),
      quadrature_(gauss_points_1d(degree)) {
  for (unsigned int i = 0; i < fe_.n_dofs_per_cell(); ++i) {
    local_component_.push_back(fe_.system_to_component_index(i).first);
    local_node_.push_back(fe_.system_to_component_index(i).second);
  }
  const SimulationMeshPart part = scatter_mesh_part(problem, comm_);
  if (element_degree_ == 2) {
    // The traction recovery and the edges' numbering read the whole surface.
    if (dealii::Utilities::MPI::min(problem.mesh ? 1 : 0, comm_) == 0)
      throw std::invalid_argument(
          "fem backend: Finite elements/Element degree = 2 needs the garment mesh on every rank "
          "(only linear triangles, degree 1, run with it on rank 0 alone)");
    whole_mesh_ = problem.mesh;
    number_edges(whole_mesh_->triangles);
  }
  n_vertices_ = part.n_vertices;
  n_all_cells_ = part.n_triangles;
  n_nodes_ = n_vertices_ + static_cast<int>(edge_ends_.size());
  mean_edge_m_ = part.mean_triangle_edge_m;
  mean_rest_edge_m_ = part.mean_rest_edge_m;
  rest_area_m2_ = part.rest_area_m2;
  constraints_ = part.constraints;
  {
    // The triangulation (this rank's cells and their ghosts) and the DoF handler live only
    // while the arrays are built.
    dealii::parallel::fullydistributed::Triangulation<2> triangulation(comm_);
    triangulation.create_triangulation(own_cells_description(part, comm_));
    dealii::DoFHandler<2> dof_handler(triangulation);
    dof_handler.distribute_dofs(fe_);
    owned_dofs_ = dof_handler.locally_owned_dofs();
    keep_relevant_nodes(exchange_node_copies(build_cells(dof_handler, part), n_nodes_, comm_));
  }
  if (element_degree_ == 2) {
    // Each cell's corners from the rank that owns it (the others add zeros).
    MPI_Allreduce(MPI_IN_PLACE, cell_vertices_.data(), static_cast<int>(3 * cell_vertices_.size()),
                  MPI_INT, MPI_SUM, comm_);
  }
  dofs_in_node_blocks_ =
      owned_dofs_.is_contiguous() && owned_dofs_.n_elements() % 3 == 0 &&
      (owned_dofs_.n_elements() == 0 || owned_dofs_.nth_index_in_set(0) % 3 == 0);
  for (int node = 0; node < n_local_nodes(); ++node)
    for (const DofTriple& d : copies(node))
      dofs_in_node_blocks_ =
          dofs_in_node_blocks_ && d[0] % 3 == 0 && d[1] == d[0] + 1 && d[2] == d[0] + 2;
  // On every rank alike: the coordinates' vector and the matrix's block size are collective.
  dofs_in_node_blocks_ = dealii::Utilities::MPI::min(dofs_in_node_blocks_ ? 1 : 0, comm_) == 1;
  {
    ConstrainedDirections every_node(constraints_, n_vertices_);
    // An edge midpoint is constrained along what both its ends are.
    for (const auto& ends : edge_ends_) every_node.add_shared(ends[0], ends[1]);
    node_constrained_ = every_node.copies(global_nodes_);
  }
  sum_node_lengths_and_areas(part);
  release_freed_memory();
}

void ReferenceMesh::sum_node_lengths_and_areas(const SimulationMeshPart& part) {
  // Of every node (8 bytes a node each, while they are summed), from this rank's own cells.
  std::vector<double> length_sum_m(n_vertices_, 0.0), count(n_vertices_, 0.0);
  std::vector<double> area_m2(n_nodes_, 0.0);
  for (const int t : cell_index_) {
    const MeshPartTriangle& triangle = part.triangle(t);
    add_node_edge_lengths(triangle.welded, triangle.rest_m, length_sum_m, count);
    add_nodal_rest_areas(triangle.welded, rest_triangle_area(triangle.rest_m), n_vertices_,
                         edge_index_, element_degree_, area_m2);
  }
  for (std::vector<double>* sums : {&length_sum_m, &count, &area_m2})
    MPI_Allreduce(MPI_IN_PLACE, sums->data(), static_cast<int>(sums->size()), MPI_DOUBLE, MPI_SUM,
                  comm_);
  const std::vector<double> every_node =
      node_edge_lengths_m(length_sum_m, count, edge_ends_, element_degree_);
  node_edge_m_.clear();
  node_contact_area_m2_.clear();
  node_edge_m_.reserve(n_local_nodes());
  node_contact_area_m2_.reserve(n_local_nodes());
  for (const int global : global_nodes_) {
    node_edge_m_.push_back(every_node[global]);
    node_contact_area_m2_.push_back(area_m2[global]);
  }
}

int ReferenceMesh::find_node(int global) const {
  const auto it = std::lower_bound(global_nodes_.begin(), global_nodes_.end(), global);
  return it != global_nodes_.end() && *it == global ? static_cast<int>(it - global_nodes_.begin())
                                                    : -1;
}

void ReferenceMesh::number_edges(const std::vector<Triangle>& welded_triangles) {
  // FE_SimplexP(2)'s midpoints follow its corners' edges (0,1), (1,2), (2,0), as here (a
  // triangle's welded corners are its panel corners' welded vertices, in the same order).
  for (const Triangle& corners : welded_triangles)
    for (int k = 0; k < 3; ++k) {
      std::array<int, 2> ends{corners[k], corners[(k + 1) % 3]};
      std::sort(ends.begin(), ends.end());
      if (edge_index_.emplace(ends, static_cast<int>(edge_ends_.size())).second)
        edge_ends_.push_back(ends);
    }
}

std::vector<NodeCopy> ReferenceMesh::build_cells(const dealii::DoFHandler<2>& dof_handler,
                                                 const SimulationMeshPart& part) {
  const unsigned int n_local = fe_.n_dofs_per_cell();
  const unsigned int n_nodes_per_cell = n_local / 3;
  // Each element node's cell corners, from the barycentric coordinates of its support point
  // on the reference triangle (corners (0,0), (1,0), (0,1)): one corner for a vertex node,
  // two for an edge midpoint.
  const dealii::FiniteElement<2>& base = fe_.base_element(0);
  std::vector<std::vector<unsigned int>> corners(n_nodes_per_cell);
  for (unsigned int a = 0; a < n_nodes_per_cell; ++a) {
    const dealii::Point<2> p = base.get_unit_support_points()[a];
    const std::array<double, 3> barycentric{1.0 - p[0] - p[1], p[0], p[1]};
    for (unsigned int v = 0; v < 3; ++v)
      if (barycentric[v] > 1e-12) corners[a].push_back(v);
    if (corners[a].size() > 2)
      throw std::logic_error("fem backend: an element node inside the cell is not supported");
  }
  // Linear hats: the barycentric coordinates of the point on the reference triangle.
  hat_values_.clear();
  shape_values_.clear();
  for (unsigned int q = 0; q < quadrature_.size(); ++q) {
    const dealii::Point<2> p = quadrature_.point(q);
    hat_values_.push_back({1.0 - p[0] - p[1], p[0], p[1]});
    shape_values_.emplace_back(n_nodes_per_cell);
    for (unsigned int a = 0; a < n_nodes_per_cell; ++a)
      shape_values_[q][a] = base.shape_value(a, p);
  }
  if (element_degree_ == 2) cell_vertices_.assign(n_all_cells_, {0, 0, 0});

  dealii::FEValues<2> fe_values(mapping_, fe_, quadrature_,
                                dealii::update_gradients | dealii::update_JxW_values);
  cell_dofs_.reset(n_local);
  cell_JxW_m2_.reset(quadrature_.size());
  cell_grad_grain_.reset(quadrature_.size() * n_nodes_per_cell);
  cell_node_rest_area_m2_.reset(n_nodes_per_cell);
  std::vector<double> JxW(quadrature_.size());
  std::vector<Vec2> grad_grain(quadrature_.size() * n_nodes_per_cell);
  std::vector<GlobalDof> dofs(n_local);
  std::vector<double> node_area_m2(n_nodes_per_cell);
  std::vector<DofTriple> triples(n_nodes_per_cell);
  std::vector<NodeCopy> node_copies;
  std::size_t merged_copies = 0;
  for (const auto& cell : dof_handler.active_cell_iterators()) {
    if (!cell->is_locally_owned()) continue;
    const int t = static_cast<int>(cell->id().get_coarse_cell_id());
    const MeshPartTriangle& triangle = part.triangle(t);
    // The cell's corners among its triangle's, by position (deal.II may order them its own
    // way): unwelded and welded vertex, grain and layout coordinates.
    std::array<int, 3> unwelded{}, welded{};
    std::array<Vec2, 3> grain, layout;
    for (unsigned int v = 0; v < 3; ++v) {
      layout[v] = Vec2(cell->vertex(v)[0], cell->vertex(v)[1]);
      int k = 0;
      for (int j = 1; j < 3; ++j)
        if ((triangle.layout_m[j] - layout[v]).squaredNorm() <
            (triangle.layout_m[k] - layout[v]).squaredNorm())
          k = j;
      unwelded[v] = triangle.unwelded[k];
      welded[v] = triangle.welded[k];
      grain[v] = triangle.rest_m[k];
    }
    // The affine map from layout to grain coordinates, J = dX_grain / dX_layout, read off the
    // rest triangle; shape gradients then transform as grad_grain = J^-T grad_layout.
    Mat2 dg, dl;
    dg << grain[1] - grain[0], grain[2] - grain[0];
    dl << layout[1] - layout[0], layout[2] - layout[0];
    const Mat2 G = (dg * dl.inverse()).inverse().transpose();
    // grain area / layout area = |det J| = 1/|det G|.
    const double grain_area_ratio = 1.0 / std::abs(G.determinant());

    fe_values.reinit(cell);
    cell->get_dof_indices(dofs);
    std::fill(node_area_m2.begin(), node_area_m2.end(), 0.0);
    for (unsigned int q = 0; q < quadrature_.size(); ++q) {
      JxW[q] = fe_values.JxW(q);
      for (unsigned int a = 0; a < n_nodes_per_cell; ++a)
        node_area_m2[a] += shape_values_[q][a] * JxW[q] * grain_area_ratio;
      for (unsigned int i = 0; i < n_local; ++i) {
        if (local_component_[i] != 0) continue;
        const dealii::Tensor<1, 2> g = fe_values.shape_grad(i, q);
        grad_grain[q * n_nodes_per_cell + local_node_[i]] = G * Vec2(g[0], g[1]);
      }
    }
    cell_index_.push_back(t);
    cell_corners_.push_back(triangle.welded);
    cell_dofs_.push_back(dofs);
    cell_grain_area_ratio_.push_back(grain_area_ratio);
    cell_node_rest_area_m2_.push_back(node_area_m2);
    cell_JxW_m2_.push_back(JxW);
    cell_grad_grain_.push_back(grad_grain);
    if (element_degree_ == 2)
      for (unsigned int v = 0; v < 3; ++v) cell_vertices_[t][v] = welded[v];

    // Each element node's copy: a corner's unwelded vertex orders its welded vertex's copies,
    // the cell its edge's midpoint's.
    for (unsigned int i = 0; i < n_local; ++i)
      triples[local_node_[i]][local_component_[i]] = dofs[i];
    for (unsigned int a = 0; a < n_nodes_per_cell; ++a) {
      NodeCopy copy;
      copy.dofs = triples[a];
      copy.rest_area_m2 = node_area_m2[a];
      if (corners[a].size() == 1) {
        copy.order = unwelded[corners[a][0]];
        copy.node = welded[corners[a][0]];
      } else {
        std::array<int, 2> ends{welded[corners[a][0]], welded[corners[a][1]]};
        std::sort(ends.begin(), ends.end());
        copy.order = t;
        copy.node = n_vertices_ + edge_index_.at(ends);
      }
      node_copies.push_back(copy);
    }
    // A copy recurs in each of its cells (six times for an inner vertex): merged as they
    // come, the list stays within about twice the rank's copies.
    if (node_copies.size() >= 2 * merged_copies + 4096) {
      merge_repeated_copies(node_copies);
      merged_copies = node_copies.size();
    }
  }
  cell_corners_.shrink_to_fit();
  cell_dofs_.shrink_to_fit();
  cell_JxW_m2_.shrink_to_fit();
  cell_grad_grain_.shrink_to_fit();
  cell_node_rest_area_m2_.shrink_to_fit();
  return node_copies;
}

void ReferenceMesh::keep_relevant_nodes(const std::vector<NodeCopy>& node_copies) {
  std::vector<GlobalDof> relevant;
  global_nodes_.clear();
  node_copies_ = CompactLists<DofTriple>();
  node_rest_area_m2_.clear();
  owned_nodes_.clear();
  seam_nodes_.clear();
  std::vector<DofTriple> copies;
  for (std::size_t begin = 0, end = 0; begin < node_copies.size(); begin = end) {
    const int global = node_copies[begin].node;
    copies.clear();
    for (; end < node_copies.size() && node_copies[end].node == global; ++end)
      copies.push_back(node_copies[end].dofs);
    const int node = n_local_nodes();
    global_nodes_.push_back(global);
    node_copies_.push_back(copies);
    node_rest_area_m2_.push_back(node_copies[begin].rest_area_m2);
    for (const DofTriple& d : copies) relevant.insert(relevant.end(), d.begin(), d.end());
    if (owned_dofs_.is_element(copies.front()[0])) owned_nodes_.push_back(node);
    for (std::size_t k = 1; k < copies.size(); ++k)
      if (owned_dofs_.is_element(copies[k][0])) {
        seam_nodes_.push_back(node);
        break;
      }
  }
  global_nodes_.shrink_to_fit();
  node_copies_.shrink_to_fit();
  node_rest_area_m2_.shrink_to_fit();
  owned_nodes_.shrink_to_fit();
  std::sort(relevant.begin(), relevant.end());
  relevant_dofs_ = dealii::IndexSet(n_dofs());
  relevant_dofs_.add_indices(relevant.begin(), relevant.end());
  relevant_dofs_.add_indices(owned_dofs_);
  relevant_dofs_.compress();
  partitioner_ = std::make_shared<const dealii::Utilities::MPI::Partitioner>(owned_dofs_,
                                                                             relevant_dofs_, comm_);
}

void ReferenceMesh::set_node_position(DofVector& x, int node, const Vec3& p) const {
  // A local node's copies are all relevant here (keep_relevant_nodes).
  for (const DofTriple& d : copies(node))
    for (int c = 0; c < 3; ++c) x(d[c]) = p[c];
}

void ReferenceMesh::copy_seams(DofVector& x) const {
  x.update_ghost_values();
  for (const int node : seam_nodes_) {
    const ListView<DofTriple> node_copies = copies(node);
    for (std::size_t k = 1; k < node_copies.size(); ++k)
      if (owned_dofs_.is_element(node_copies[k][0]))
        for (int c = 0; c < 3; ++c) x(node_copies[k][c]) = x(node_copies.front()[c]);
  }
  x.update_ghost_values();
}

DofVector ReferenceMesh::dof_positions(const std::vector<Vec3>& positions_m) const {
  DofVector x = dof_vector();
  for (int node = 0; node < n_local_nodes(); ++node) {
    const int global = global_nodes_[node];
    if (global < n_vertices_) {
      set_node_position(x, node, positions_m[global]);
    } else {
      // Midpoints start on their chords; the contact predictor lifts those inside the body.
      const std::array<int, 2>& ends = edge_ends_[global - n_vertices_];
      set_node_position(x, node, 0.5 * (positions_m[ends[0]] + positions_m[ends[1]]));
    }
  }
  x.update_ghost_values();
  return x;
}

template <typename T>
std::vector<T> ReferenceMesh::gather_nodes(const std::vector<T>& owned_values) const {
  static_assert(sizeof(T) % sizeof(double) == 0, "gather_nodes: values of doubles only");
  T zero;
  if constexpr (std::is_same_v<T, double>)
    zero = 0.0;
  else
    zero = T::Zero();
  std::vector<T> whole(n_nodes(), zero);
  for (int k = 0; k < n_owned_nodes(); ++k) whole[global_nodes_[owned_nodes_[k]]] = owned_values[k];
  MPI_Allreduce(MPI_IN_PLACE, reinterpret_cast<double*>(whole.data()),
                static_cast<int>(whole.size() * (sizeof(T) / sizeof(double))), MPI_DOUBLE, MPI_SUM,
                comm_);
  return whole;
}
template std::vector<double> ReferenceMesh::gather_nodes(const std::vector<double>&) const;
template std::vector<Vec3> ReferenceMesh::gather_nodes(const std::vector<Vec3>&) const;

std::vector<Vec3> ReferenceMesh::vertex_positions(const DofVector& x) const {
  std::vector<Vec3> owned_positions(n_owned_nodes());
  for (int k = 0; k < n_owned_nodes(); ++k) owned_positions[k] = node_position(x, owned_nodes_[k]);
  std::vector<Vec3> positions = gather_nodes(owned_positions);
  positions.resize(n_vertices_);  // the vertices come first
  return positions;
}

std::vector<double> ReferenceMesh::node_rest_area_m2() const {
  std::vector<double> owned_area_m2(n_owned_nodes());
  for (int k = 0; k < n_owned_nodes(); ++k) owned_area_m2[k] = node_rest_area_m2_[owned_nodes_[k]];
  return gather_nodes(owned_area_m2);
}

}  // namespace tightfit
