// The finite-element membrane backend: mesh, degrees of freedom, constraints, assembly,
// PETSc solves and Newton's method with augmented-Lagrangian contact. The one translation
// unit of the backend that includes deal.II's finite-element and PETSc headers.
#include "fem/fem_backend.h"

#include "contact/cylinder.h"
#include "contact/nodal_contact.h"
#include "core/constrained_directions.h"
#include "core/interruption.h"
#include "core/mesh_geometry.h"
#include "fem/membrane_kernel.h"
#include "fem/petsc_linear_solver.h"
#include "fem/traction_recovery.h"

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/reference_cell.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>
#include <deal.II/lac/vector.h>

#include <petscsys.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <sstream>

namespace tightfit {

namespace {

using dealii::types::global_dof_index;
using DofTriple = std::array<global_dof_index, 3>;

// Starts MPI and PETSc when the program has not (tests, a serial driver); they are finalised
// at exit.
void start_mpi_and_petsc() {
  int mpi_started = 0;
  MPI_Initialized(&mpi_started);
  if (!mpi_started) {
    static int argc = 1;
    static char program[] = "tightfit";
    static char* arguments[] = {program, nullptr};
    static char** argv = arguments;
    static dealii::Utilities::MPI::MPI_InitFinalize runtime(argc, argv, 1);
    return;
  }
  PetscBool petsc_started = PETSC_FALSE;
  PetscInitialized(&petsc_started);
  if (!petsc_started) PetscInitializeNoArguments();
}

// The panels' own triangles (unwelded vertex indices), recovered from the welded mesh: each
// corner is the copy of its welded vertex inside the triangle's panel; where a panel holds two
// copies (a one-panel tube), the copies whose layout edge lengths match the rest triangle win.
std::vector<Triangle> unwelded_triangles(const SimulationMesh& mesh) {
  const int n_unwelded = mesh.n_unwelded_vertices();
  std::vector<std::multimap<int, int>> copies(mesh.panel_vertex_offset.size());
  for (std::size_t p = 0; p < mesh.panel_vertex_offset.size(); ++p) {
    const int end =
        p + 1 < mesh.panel_vertex_offset.size() ? mesh.panel_vertex_offset[p + 1] : n_unwelded;
    for (int u = mesh.panel_vertex_offset[p]; u < end; ++u)
      copies[p].emplace(mesh.welded_index[u], u);
  }
  std::vector<Triangle> result;
  result.reserve(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& panel_copies = copies[mesh.triangle_panel[t]];
    std::array<std::vector<int>, 3> candidates;
    for (int k = 0; k < 3; ++k) {
      const auto range = panel_copies.equal_range(mesh.triangles[t][k]);
      for (auto it = range.first; it != range.second; ++it) candidates[k].push_back(it->second);
    }
    const auto& rest = mesh.rest_triangles[t];
    double best_mismatch = std::numeric_limits<double>::infinity();
    Triangle best{};
    for (int a : candidates[0])
      for (int b : candidates[1])
        for (int c : candidates[2]) {
          const std::array<int, 3> u{a, b, c};
          double mismatch = 0.0;
          for (int k = 0; k < 3; ++k) {
            const int l = (k + 1) % 3;
            const double layout =
                (mesh.layout_positions_m[u[l]] - mesh.layout_positions_m[u[k]]).norm();
            const double grain = (rest[l] - rest[k]).norm();
            mismatch += (layout - grain) * (layout - grain);
          }
          if (mismatch < best_mismatch) {
            best_mismatch = mismatch;
            best = {a, b, c};
          }
        }
    result.push_back(best);
  }
  return result;
}

// Adds homogeneous constraints dx . d = 0 for each direction d on one vertex's three DoFs.
// Each direction eliminates one component, chosen after removing the components the earlier
// directions eliminated, so the constraints never form a cycle.
void constrain_directions(const DofTriple& dofs, std::vector<Vec3> directions,
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

std::string format_list(const std::vector<double>& values) {
  std::ostringstream out;
  out.precision(2);
  out << std::scientific;
  for (std::size_t i = 0; i < values.size(); ++i) out << (i ? " " : "") << values[i];
  return out.str();
}

}  // namespace

class FemBackend::Implementation {
 public:
  Implementation(const Problem& problem, const FemParameters& parameters);

  void set_positions(const std::vector<Vec3>& positions_m);
  StepReport solve(const LoadStep& step);

  void linearise(const std::vector<Vec3>& node_positions_m, Eigen::VectorXd& residual_N,
                 Eigen::MatrixXd& tangent_N_per_m) const;
  std::vector<Vec3> node_positions(const std::vector<Vec3>& vertex_positions_m) const;
  std::vector<Vec3> internal_force_N(const dealii::Vector<double>& x) const;
  dealii::Vector<double> dof_positions(const std::vector<Vec3>& positions_m) const;

  SurfaceState state_;
  std::vector<double> traction_Pa_;
  std::vector<double> history_N_;
  double max_penetration_m_ = 0.0;
  const std::vector<double>& multipliers_N() const { return multiplier_N_; }

 private:
  void build_mesh();
  // The contact nodes (welded vertices, then for degree 2 the welded edges' midpoints), the
  // DoFs of each of their copies, and each cell's corners.
  void build_nodes();
  // Penalty stiffness k w_k of each node from positive nodal rest areas w_k (see the body).
  void build_penalties();
  // Shape-function gradients in grain axes and JxW at every quadrature point of every cell:
  // they live on the reference (pattern) configuration, so they are computed once.
  void build_cell_quadrature();
  void build_constraints_and_matrix();
  Vec3 vertex_position(const dealii::Vector<double>& x, int unwelded) const;
  Vec3 node_position(const dealii::Vector<double>& x, int node) const;
  // Writes p into every copy of the node (seams keep copies equal).
  void set_node_position(dealii::Vector<double>& x, int node, const Vec3& p) const;
  int n_nodes() const { return static_cast<int>(node_copies_.size()); }
  // Node-major energy gradient (and Hessian) of one cell, from the DoF values x.
  void cell_kernel(unsigned int cell, const dealii::Vector<double>& x, Eigen::VectorXd& gradient,
                   Eigen::MatrixXd* hessian) const;
  // rhs = -R(x) with R = dPi/dx - f_contact, constrained; the tangent dR/dx when asked.
  void assemble(const dealii::Vector<double>& x, bool with_tangent);
  // Solves tangent * increment = rhs; returns the Krylov iterations (0 for direct).
  int solve_linear_system(const LoadStep& step, std::string& notes);
  dealii::Vector<double> gather_increment() const;
  int newton(const LoadStep& step, std::vector<int>& krylov_iterations, std::string& notes);
  // Secant extrapolation in alpha of the positions and multipliers of the last two converged
  // steps in contact (a continuation predictor: it changes the start, not the equilibrium).
  void secant_predictor(const LoadStep& step);
  void contact_predictor();
  // Solves (K + mu I) dx = -R with the tangent at x_ re-assembled; mu in N/m.
  int solve_shifted(const LoadStep& step, double shift_N_per_m, std::string& notes);
  void update_state();
  // Degree 2: each welded vertex reads the traction recovered on the curved surface.
  void update_state_from_recovered_traction();
  [[noreturn]] void fail(const LoadStep& step, const std::string& what, double residual_N) const;

  Problem problem_;
  FemParameters parameters_;
  MPI_Comm comm_ = MPI_COMM_WORLD;
  const Cylinder* cylinder_ = nullptr;

  dealii::parallel::shared::Triangulation<2> triangulation_;
  dealii::FESystem<2> fe_;
  dealii::MappingFE<2> mapping_;
  dealii::QGaussSimplex<2> quadrature_;
  dealii::DoFHandler<2> dof_handler_;
  dealii::IndexSet owned_dofs_;
  // Local DoF i of a cell is component local_component_[i] of node local_node_[i].
  std::vector<int> local_component_, local_node_;

  std::vector<DofTriple> vertex_dofs_;   // unwelded vertex -> its three DoFs
  std::vector<int> master_;              // welded vertex -> the unwelded copy that carries it
  std::vector<Mat2> to_grain_gradient_;  // per active cell: grad_grain = G grad_layout
  // Per active cell (by active_cell_index): its DoFs, and per quadrature point its JxW (m^2)
  // and each node's shape gradient in grain axes (1/m), node-major.
  std::vector<std::vector<global_dof_index>> cell_dofs_;
  std::vector<std::vector<double>> cell_JxW_m2_;
  std::vector<std::vector<Vec2>> cell_grad_grain_;
  std::vector<char> cell_owned_;
  // Contact nodes: welded vertex w is node w; with degree 2, welded edge e's midpoint is node
  // n_vertices + e. Per node, the DoFs of each copy (one per panel it lies in); the first
  // carries it, the others follow it (seam constraints).
  std::vector<std::vector<DofTriple>> node_copies_;
  std::vector<std::array<int, 2>> edge_ends_;      // welded edge -> its two welded vertices
  std::map<std::array<int, 2>, int> edge_index_;   // sorted welded vertex pair -> welded edge
  ConstrainedDirections node_constrained_;         // the Problem's constraints at every node
  std::vector<std::array<int, 3>> cell_vertices_;  // per cell, its corners' welded vertices
  // The linear hat of each cell corner at the quadrature points [q][v], and per cell the ratio
  // of grain to layout area (quadrature weights are layout areas).
  std::vector<std::vector<double>> hat_values_;
  std::vector<double> cell_grain_area_ratio_;

  dealii::AffineConstraints<double> constraints_;
  dealii::PETScWrappers::MPI::SparseMatrix tangent_;
  dealii::PETScWrappers::MPI::Vector rhs_, increment_;
  std::unique_ptr<PetscLinearSolver> linear_solver_;
  dealii::Vector<double> x_;  // every DoF on every rank: the current positions, m

  std::vector<double> penalty_N_per_m_;  // k w per node (w its positive nodal rest area)
  std::vector<double> multiplier_N_;     // augmented-Lagrangian estimate per node
  double mean_edge_m_ = 0.0;
  double force_scale_N_ = 0.0;
  double normal_step_m_ = 0.0;
  bool had_contact_ = false;
  // The last two converged steps (alpha, DoF positions, multipliers), for secant_predictor.
  int n_history_ = 0;
  std::array<double, 2> history_alpha_{};
  std::array<dealii::Vector<double>, 2> history_x_;
  std::array<std::vector<double>, 2> history_multiplier_N_;
  // Levenberg-Marquardt shift of the tangent from line-search failures, N/m (the residual's
  // own shift, 'Residual shift factor', is added in newton()).
  double shift_N_per_m_ = 0.0;
  int n_shifted_solves_ = 0;  // in the current step
  // Relative tolerance of the next Krylov solve (inexact Newton, see newton()).
  double krylov_tolerance_ = 1e-10;
};

FemBackend::Implementation::Implementation(const Problem& problem, const FemParameters& parameters)
    : problem_(problem),
      parameters_(parameters),
      triangulation_(MPI_COMM_WORLD),
      fe_(dealii::FE_SimplexP<2>(parameters.element_degree), 3),
      mapping_(dealii::FE_SimplexP<2>(1)),
      quadrature_(gauss_points_1d(parameters.element_degree)),
      dof_handler_(triangulation_) {
  if (!problem.mesh || !problem.law || !problem.body)
    throw std::invalid_argument("fem backend: the problem needs a mesh, a law and a body");
  cylinder_ = dynamic_cast<const Cylinder*>(problem.body);
  const SimulationMesh& mesh = *problem.mesh;

  build_mesh();
  dof_handler_.distribute_dofs(fe_);
  owned_dofs_ = dof_handler_.locally_owned_dofs();
  for (unsigned int i = 0; i < fe_.n_dofs_per_cell(); ++i) {
    local_component_.push_back(fe_.system_to_component_index(i).first);
    local_node_.push_back(fe_.system_to_component_index(i).second);
  }
  vertex_dofs_.assign(mesh.n_unwelded_vertices(), DofTriple{});
  for (const auto& cell : dof_handler_.active_cell_iterators())
    for (unsigned int v = 0; v < cell->n_vertices(); ++v)
      for (unsigned int c = 0; c < 3; ++c)
        vertex_dofs_[cell->vertex_index(v)][c] = cell->vertex_dof_index(v, c);
  master_.assign(mesh.n_vertices, -1);
  for (int u = 0; u < mesh.n_unwelded_vertices(); ++u)
    if (master_[mesh.welded_index[u]] < 0) master_[mesh.welded_index[u]] = u;
  build_nodes();
  build_cell_quadrature();
  linear_solver_ = std::make_unique<PetscLinearSolver>(parameters.linear_solver,
                                                       parameters.max_linear_iterations, comm_);

  double edge_sum = 0.0;
  for (const auto& r : mesh.rest_triangles)
    edge_sum += (r[1] - r[0]).norm() + (r[2] - r[1]).norm() + (r[0] - r[2]).norm();
  mean_edge_m_ = edge_sum / (3.0 * mesh.rest_triangles.size());
  force_scale_N_ = problem.law->stiffness_scale() * mean_edge_m_;
  normal_step_m_ = 1e-6 * mean_edge_m_;
  build_penalties();
  multiplier_N_.assign(n_nodes(), 0.0);

  // Start flat in the layout plane until the caller places the garment.
  std::vector<Vec3> flat(mesh.n_vertices);
  for (int u = 0; u < mesh.n_unwelded_vertices(); ++u)
    flat[mesh.welded_index[u]] =
        Vec3(mesh.layout_positions_m[u].x(), mesh.layout_positions_m[u].y(), 0);
  set_positions(flat);
}

void FemBackend::Implementation::build_mesh() {
  const SimulationMesh& mesh = *problem_.mesh;
  const std::vector<Triangle> panel_triangles = unwelded_triangles(mesh);
  std::vector<dealii::Point<2>> vertices;
  for (const Vec2& x : mesh.layout_positions_m) vertices.emplace_back(x.x(), x.y());
  std::vector<dealii::CellData<2>> cells(panel_triangles.size(), dealii::CellData<2>(3));
  std::map<std::array<int, 3>, int> triangle_of_corners;
  for (std::size_t t = 0; t < panel_triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) cells[t].vertices[k] = panel_triangles[t][k];
    cells[t].material_id = mesh.triangle_panel[t];
    std::array<int, 3> key = panel_triangles[t];
    std::sort(key.begin(), key.end());
    triangle_of_corners[key] = static_cast<int>(t);
  }
  triangulation_.create_triangulation(vertices, cells, dealii::SubCellData());

  // Per cell, the affine map from layout to grain coordinates, J = dX_grain / dX_layout, read
  // off the rest triangle; shape gradients then transform as grad_grain = J^-T grad_layout.
  to_grain_gradient_.assign(triangulation_.n_active_cells(), Mat2::Identity());
  for (const auto& cell : triangulation_.active_cell_iterators()) {
    std::array<int, 3> key;
    for (int v = 0; v < 3; ++v) key[v] = cell->vertex_index(v);
    std::array<int, 3> sorted = key;
    std::sort(sorted.begin(), sorted.end());
    const int t = triangle_of_corners.at(sorted);
    std::array<Vec2, 3> grain, layout;
    for (int v = 0; v < 3; ++v) {
      const int k =
          static_cast<int>(std::find(panel_triangles[t].begin(), panel_triangles[t].end(), key[v]) -
                           panel_triangles[t].begin());
      grain[v] = mesh.rest_triangles[t][k];
      layout[v] = mesh.layout_positions_m[key[v]];
    }
    Mat2 dg, dl;
    dg << grain[1] - grain[0], grain[2] - grain[0];
    dl << layout[1] - layout[0], layout[2] - layout[0];
    const Mat2 J = dg * dl.inverse();
    to_grain_gradient_[cell->active_cell_index()] = J.inverse().transpose();
  }
}

void FemBackend::Implementation::build_nodes() {
  const SimulationMesh& mesh = *problem_.mesh;
  node_copies_.assign(mesh.n_vertices, {});
  for (int w = 0; w < mesh.n_vertices; ++w) node_copies_[w].push_back(vertex_dofs_[master_[w]]);
  for (int u = 0; u < mesh.n_unwelded_vertices(); ++u)
    if (master_[mesh.welded_index[u]] != u)
      node_copies_[mesh.welded_index[u]].push_back(vertex_dofs_[u]);

  // Each element node's cell corners, from the barycentric coordinates of its support point
  // on the reference triangle (corners (0,0), (1,0), (0,1)): one corner for a vertex node,
  // two for an edge midpoint.
  const dealii::FiniteElement<2>& base = fe_.base_element(0);
  const unsigned int n_element_nodes = base.n_dofs_per_cell();
  std::vector<std::vector<unsigned int>> corners(n_element_nodes);
  for (unsigned int a = 0; a < n_element_nodes; ++a) {
    const dealii::Point<2> p = base.get_unit_support_points()[a];
    const std::array<double, 3> barycentric{1.0 - p[0] - p[1], p[0], p[1]};
    for (unsigned int v = 0; v < 3; ++v)
      if (barycentric[v] > 1e-12) corners[a].push_back(v);
    if (corners[a].size() > 2)
      throw std::logic_error("fem backend: an element node inside the cell is not supported");
  }

  // A midpoint's copies are the distinct DoF triples of the panel edges over one welded edge:
  // the same edge seen from its two cells in one panel shares its DoFs; a seam edge has a copy
  // in each panel.
  const unsigned int n_local = fe_.n_dofs_per_cell();
  std::vector<global_dof_index> dofs(n_local);
  std::vector<DofTriple> triples(n_element_nodes);
  std::vector<std::vector<DofTriple>> midpoint_copies;
  cell_vertices_.assign(triangulation_.n_active_cells(), {});
  for (const auto& cell : dof_handler_.active_cell_iterators()) {
    cell->get_dof_indices(dofs);
    for (unsigned int i = 0; i < n_local; ++i)
      triples[local_node_[i]][local_component_[i]] = dofs[i];
    for (unsigned int v = 0; v < 3; ++v)
      cell_vertices_[cell->active_cell_index()][v] = mesh.welded_index[cell->vertex_index(v)];
    for (unsigned int a = 0; a < n_element_nodes; ++a) {
      if (corners[a].size() == 1) continue;
      std::array<int, 2> ends{};
      for (std::size_t k = 0; k < 2; ++k)
        ends[k] = mesh.welded_index[cell->vertex_index(corners[a][k])];
      std::sort(ends.begin(), ends.end());
      const auto [it, inserted] = edge_index_.emplace(ends, static_cast<int>(edge_ends_.size()));
      if (inserted) {
        edge_ends_.push_back(ends);
        midpoint_copies.emplace_back();
      }
      std::vector<DofTriple>& copies = midpoint_copies[it->second];
      if (std::find(copies.begin(), copies.end(), triples[a]) == copies.end())
        copies.push_back(triples[a]);
    }
  }
  for (auto& copies : midpoint_copies) node_copies_.push_back(std::move(copies));

  // Constrained vertices keep their constraints; an edge midpoint is constrained along what
  // both its ends are.
  node_constrained_ = ConstrainedDirections(problem_.constraints, mesh.n_vertices);
  for (const auto& ends : edge_ends_) node_constrained_.add_shared(ends[0], ends[1]);
}

// Nodal contact acts at every node with the penalty k w_k, k = beta Y / h^2 (Pa/m) and w_k a
// positive rest area per node. Linear triangles: the barycentric third of each triangle (their
// lumped mass). Quadratic triangles: their lumped (row-sum) mass gives the corners zero area,
// which would leave them without contact, so each triangle is split at its edge midpoints into
// four linear triangles of area A/4 whose lumped masses give A/12 to each corner and A/4 to
// each midpoint (3 x A/12 + 3 x A/4 = A). These weights only set the penalty, which the
// augmented-Lagrangian updates remove from the converged state.
void FemBackend::Implementation::build_penalties() {
  const SimulationMesh& mesh = *problem_.mesh;
  const double k_Pa_per_m =
      parameters_.penalty_factor * problem_.law->stiffness_scale() / (mean_edge_m_ * mean_edge_m_);
  const bool quadratic = parameters_.element_degree == 2;
  const std::vector<double> areas = rest_triangle_areas(mesh);
  penalty_N_per_m_.assign(n_nodes(), 0.0);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& v = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) {
      penalty_N_per_m_[v[k]] += k_Pa_per_m * areas[t] / (quadratic ? 12.0 : 3.0);
      if (!quadratic) continue;
      std::array<int, 2> ends{v[k], v[(k + 1) % 3]};
      std::sort(ends.begin(), ends.end());
      penalty_N_per_m_[mesh.n_vertices + edge_index_.at(ends)] += k_Pa_per_m * areas[t] / 4.0;
    }
  }
}

void FemBackend::Implementation::build_cell_quadrature() {
  dealii::FEValues<2> fe_values(mapping_, fe_, quadrature_,
                                dealii::update_gradients | dealii::update_JxW_values);
  const unsigned int n_cells = triangulation_.n_active_cells();
  const unsigned int n_local = fe_.n_dofs_per_cell();
  const unsigned int n_element_nodes = n_local / 3;
  cell_dofs_.assign(n_cells, std::vector<global_dof_index>(n_local));
  cell_JxW_m2_.assign(n_cells, {});
  cell_grad_grain_.assign(n_cells, {});
  cell_owned_.assign(n_cells, 0);
  cell_grain_area_ratio_.assign(n_cells, 1.0);
  // Linear hats: the barycentric coordinates of the point on the reference triangle.
  hat_values_.clear();
  for (unsigned int q = 0; q < quadrature_.size(); ++q) {
    const dealii::Point<2> p = quadrature_.point(q);
    hat_values_.push_back({1.0 - p[0] - p[1], p[0], p[1]});
  }
  for (const auto& cell : dof_handler_.active_cell_iterators()) {
    const unsigned int c = cell->active_cell_index();
    fe_values.reinit(cell);
    cell->get_dof_indices(cell_dofs_[c]);
    cell_owned_[c] = cell->is_locally_owned();
    const Mat2& G = to_grain_gradient_[c];
    // grad_grain = G grad_layout with G = J^-T: grain area / layout area = |det J| = 1/|det G|.
    cell_grain_area_ratio_[c] = 1.0 / std::abs(G.determinant());
    cell_grad_grain_[c].resize(quadrature_.size() * n_element_nodes);
    for (unsigned int q = 0; q < quadrature_.size(); ++q) {
      cell_JxW_m2_[c].push_back(fe_values.JxW(q));
      for (unsigned int i = 0; i < n_local; ++i) {
        if (local_component_[i] != 0) continue;
        const dealii::Tensor<1, 2> g = fe_values.shape_grad(i, q);
        cell_grad_grain_[c][q * n_element_nodes + local_node_[i]] = G * Vec2(g[0], g[1]);
      }
    }
  }
}

void FemBackend::Implementation::set_positions(const std::vector<Vec3>& positions_m) {
  if (static_cast<int>(positions_m.size()) != problem_.mesh->n_vertices)
    throw std::invalid_argument("fem backend: set_positions needs one position per vertex");
  x_ = dof_positions(positions_m);
  n_history_ = 0;
  build_constraints_and_matrix();
}

dealii::Vector<double> FemBackend::Implementation::dof_positions(
    const std::vector<Vec3>& positions_m) const {
  const int n_vertices = problem_.mesh->n_vertices;
  dealii::Vector<double> x(dof_handler_.n_dofs());
  for (int w = 0; w < n_vertices; ++w) set_node_position(x, w, positions_m[w]);
  // Midpoints start on their chords; the contact predictor lifts those inside the body.
  for (std::size_t e = 0; e < edge_ends_.size(); ++e)
    set_node_position(x, n_vertices + static_cast<int>(e),
                      0.5 * (positions_m[edge_ends_[e][0]] + positions_m[edge_ends_[e][1]]));
  return x;
}

Vec3 FemBackend::Implementation::vertex_position(const dealii::Vector<double>& x,
                                                 int unwelded) const {
  const DofTriple& d = vertex_dofs_[unwelded];
  return Vec3(x[d[0]], x[d[1]], x[d[2]]);
}

Vec3 FemBackend::Implementation::node_position(const dealii::Vector<double>& x, int node) const {
  const DofTriple& d = node_copies_[node].front();
  return Vec3(x[d[0]], x[d[1]], x[d[2]]);
}

void FemBackend::Implementation::set_node_position(dealii::Vector<double>& x, int node,
                                                   const Vec3& p) const {
  for (const DofTriple& d : node_copies_[node])
    for (int c = 0; c < 3; ++c) x[d[c]] = p[c];
}

void FemBackend::Implementation::build_constraints_and_matrix() {
  const SimulationMesh& mesh = *problem_.mesh;
  constraints_.clear();
  // Seams: every copy of a node (a welded vertex, or the midpoint of a seam edge) follows
  // the copy that carries it.
  for (const std::vector<DofTriple>& copies : node_copies_)
    for (std::size_t k = 1; k < copies.size(); ++k)
      for (int c = 0; c < 3; ++c) {
        constraints_.add_line(copies[k][c]);
        constraints_.add_entry(copies[k][c], copies[0][c], 1.0);
      }
  // Constrained nodes keep their coordinates along their constrained directions.
  for (int node = 0; node < n_nodes(); ++node)
    if (node_constrained_.constrained(node))
      constrain_directions(node_copies_[node].front(), node_constrained_.directions(node),
                           constraints_);
  // A frictionless cylinder leaves the tube free to turn about its axis and (with free ends)
  // to slide along it. One vertex near mid-height is pinned against both motions; its reaction
  // vanishes at equilibrium (no body force acts along either motion), so no pressure changes.
  if (cylinder_) {
    const Vec3 axis = cylinder_->axis().normalized();
    const Vec3 origin = cylinder_->point_on_axis_m();
    double mean_axial = 0.0;
    for (int w = 0; w < mesh.n_vertices; ++w)
      mean_axial += (vertex_position(x_, master_[w]) - origin).dot(axis);
    mean_axial /= mesh.n_vertices;
    int pinned = -1;
    double best = std::numeric_limits<double>::infinity();
    for (int w = 0; w < mesh.n_vertices; ++w) {
      const Vec3 r = vertex_position(x_, master_[w]) - origin;
      const double radial = (r - r.dot(axis) * axis).norm();
      const double distance = std::abs(r.dot(axis) - mean_axial);
      if (!node_constrained_.constrained(w) && radial > 1e-12 && distance < best - 1e-12) {
        best = distance;
        pinned = w;
      }
    }
    if (pinned >= 0) {
      const Vec3 r = vertex_position(x_, master_[pinned]) - origin;
      std::vector<Vec3> directions{axis.cross(r).normalized()};
      if (problem_.constraints.empty()) directions.push_back(axis);
      constrain_directions(vertex_dofs_[master_[pinned]], directions, constraints_);
    }
  }
  constraints_.close();

  // Every rank holds the whole (small) mesh: the pattern is built from all cells, each rank
  // keeps its own rows.
  dealii::DynamicSparsityPattern pattern(dof_handler_.n_dofs());
  std::vector<global_dof_index> dofs(fe_.n_dofs_per_cell());
  for (const auto& cell : dof_handler_.active_cell_iterators()) {
    cell->get_dof_indices(dofs);
    constraints_.add_entries_local_to_global(dofs, pattern, false);
  }
  tangent_.reinit(owned_dofs_, owned_dofs_, pattern, comm_);
  // A new matrix: its pattern may differ, so the next solve analyses it afresh.
  if (linear_solver_) linear_solver_->reset();
  rhs_.reinit(owned_dofs_, comm_);
  increment_.reinit(owned_dofs_, comm_);
}

void FemBackend::Implementation::cell_kernel(unsigned int cell, const dealii::Vector<double>& x,
                                             Eigen::VectorXd& gradient,
                                             Eigen::MatrixXd* hessian) const {
  const unsigned int n_local = fe_.n_dofs_per_cell();
  const unsigned int n_element_nodes = n_local / 3;
  const std::vector<global_dof_index>& dofs = cell_dofs_[cell];
  gradient.setZero(n_local);
  if (hessian) hessian->setZero(n_local, n_local);
  std::vector<Vec2> grad_grain(n_element_nodes);
  for (unsigned int q = 0; q < cell_JxW_m2_[cell].size(); ++q) {
    std::copy_n(cell_grad_grain_[cell].begin() + q * n_element_nodes, n_element_nodes,
                grad_grain.begin());
    // F = dx/dX_grain = sum_a x_a grad_N_a^T (the membrane's 3x2 gradient).
    Mat32 F = Mat32::Zero();
    for (unsigned int i = 0; i < n_local; ++i)
      F.row(local_component_[i]) += x[dofs[i]] * grad_grain[local_node_[i]].transpose();
    add_membrane_point(*problem_.law, grad_grain, F, cell_JxW_m2_[cell][q], gradient, hessian);
  }
}

void FemBackend::Implementation::assemble(const dealii::Vector<double>& x, bool with_tangent) {
  const unsigned int n_local = fe_.n_dofs_per_cell();
  if (with_tangent) tangent_ = 0;
  rhs_ = 0;
  dealii::FullMatrix<double> cell_matrix(n_local, n_local);
  dealii::Vector<double> cell_rhs(n_local);
  Eigen::VectorXd gradient;
  Eigen::MatrixXd hessian;
  for (unsigned int cell = 0; cell < cell_dofs_.size(); ++cell) {
    if (!cell_owned_[cell]) continue;
    cell_kernel(cell, x, gradient, with_tangent ? &hessian : nullptr);
    for (unsigned int i = 0; i < n_local; ++i) {
      const int a = 3 * local_node_[i] + local_component_[i];
      cell_rhs[i] = -gradient[a];
      if (with_tangent)
        for (unsigned int j = 0; j < n_local; ++j)
          cell_matrix(i, j) = hessian(a, 3 * local_node_[j] + local_component_[j]);
    }
    if (with_tangent)
      constraints_.distribute_local_to_global(cell_matrix, cell_rhs, cell_dofs_[cell], tangent_,
                                              rhs_);
    else
      constraints_.distribute_local_to_global(cell_rhs, cell_dofs_[cell], rhs_);
  }

  // Contact at the nodes (vertices, and midpoints for degree 2: without them the quadratic
  // edges would sink into the body as straight chords), each on the rank that owns its DoFs.
  dealii::FullMatrix<double> vertex_matrix(3, 3);
  dealii::Vector<double> vertex_rhs(3);
  std::vector<global_dof_index> vertex_dof_list(3);
  for (int node = 0; node < n_nodes(); ++node) {
    const DofTriple& d = node_copies_[node].front();
    if (!owned_dofs_.is_element(d[0])) continue;
    const NodalContact c =
        nodal_contact(*problem_.body, node_position(x, node), multiplier_N_[node],
                      penalty_N_per_m_[node], with_tangent ? normal_step_m_ : 0.0);
    if (c.multiplier_N <= 0.0 && parameters_.tangent_shift_N_per_m <= 0.0) continue;
    for (int i = 0; i < 3; ++i) {
      vertex_dof_list[i] = d[i];
      vertex_rhs[i] = c.force_N[i];
      for (int j = 0; j < 3; ++j)
        vertex_matrix(i, j) =
            c.stiffness_N_per_m(i, j) + (i == j ? parameters_.tangent_shift_N_per_m : 0.0);
    }
    if (with_tangent)
      constraints_.distribute_local_to_global(vertex_matrix, vertex_rhs, vertex_dof_list, tangent_,
                                              rhs_);
    else
      constraints_.distribute_local_to_global(vertex_rhs, vertex_dof_list, rhs_);
  }
  if (with_tangent) tangent_.compress(dealii::VectorOperation::add);
  rhs_.compress(dealii::VectorOperation::add);
}

int FemBackend::Implementation::solve_linear_system(const LoadStep& step, std::string& notes) {
  try {
    const LinearSolveResult result =
        linear_solver_->solve(tangent_.petsc_matrix(), rhs_, increment_, krylov_tolerance_);
    notes += result.note;
    return result.used == LinearSolverKind::direct ? 0 : result.iterations;
  } catch (const std::exception& e) {
    fail(step,
         std::string("linear solver '") + to_string(parameters_.linear_solver) +
             "' failed: " + e.what(),
         rhs_.linfty_norm());
  }
}

dealii::Vector<double> FemBackend::Implementation::gather_increment() const {
  dealii::Vector<double> full(dof_handler_.n_dofs());
  for (const auto i : owned_dofs_) full[i] = increment_(i);
  MPI_Allreduce(MPI_IN_PLACE, full.begin(), static_cast<int>(full.size()), MPI_DOUBLE, MPI_SUM,
                comm_);
  constraints_.distribute(full);
  return full;
}

void FemBackend::Implementation::fail(const LoadStep& step, const std::string& what,
                                      double residual_N) const {
  std::ostringstream out;
  out << "fem backend, load step " << step.index << " (alpha " << step.alpha << "): " << what
      << "; residual " << residual_N << " N (tolerance "
      << parameters_.residual_tolerance * force_scale_N_ << " N)";
  throw SolverError(out.str());
}

// Newton's method on R(x) = 0 with the consistent tangent and a backtracking line search on
// the residual norm; returns the iterations taken. The trial point of a full step is assembled
// with its tangent: when the step is accepted (the usual case near the solution) that assembly
// is the next iteration's, so a Newton iteration costs one assembly and one solve.
int FemBackend::Implementation::newton(const LoadStep& step, std::vector<int>& krylov_iterations,
                                       std::string& notes) {
  const double tolerance_N = parameters_.residual_tolerance * force_scale_N_;
  assemble(x_, true);
  for (int iteration = 0;; ++iteration) {
    const double residual_N = rhs_.linfty_norm();
    history_N_.push_back(residual_N);
    if (!std::isfinite(residual_N)) fail(step, "the residual is not finite", residual_N);
    if (residual_N <= tolerance_N) return iteration;
    // Collective, so that every rank stops at the same iteration whichever got the signal.
    throw_if_interrupted(dealii::Utilities::MPI::max(interruption_signal(), comm_),
                         "during load step " + std::to_string(step.index) + " (alpha " +
                             std::to_string(step.alpha) + ") at Newton iteration " +
                             std::to_string(iteration));
    // Inexact Newton (Eisenstat and Walker's second forcing term): solve each system only as
    // far as the residual's own decrease warrants, eta = 0.9 (|R_k| / |R_k-1|)^2 within
    // [linear tolerance, 1e-2]; convergence stays superlinear. Where the residual fell by less
    // than half (a near-singular tangent), loose solves only stall it: solve to the linear
    // tolerance.
    const double previous_N = iteration > 0 ? history_N_[history_N_.size() - 2] : 0.0;
    const double ratio = iteration > 0 ? residual_N / previous_N : 0.1;
    krylov_tolerance_ = ratio < 0.5
                            ? std::clamp(0.9 * ratio * ratio, parameters_.linear_tolerance, 1e-2)
                            : parameters_.linear_tolerance;
    if (iteration >= parameters_.max_newton_iterations)
      fail(step, "Newton's method did not converge in " + std::to_string(iteration) + " iterations",
           residual_N);
    const double norm_0 = rhs_.l2_norm();
    // A zero-stress or compressed membrane (a tube that just touches the body) has a singular
    // or indefinite tangent, along which Newton's step may be huge or useless. When the line
    // search fails, the tangent is shifted by mu I (Levenberg-Marquardt), mu growing tenfold
    // until the line search succeeds and shrinking tenfold after each success. The residual is
    // untouched, so the converged state is not biased.
    const double stiffness_scale_N_per_m = problem_.law->stiffness_scale();
    dealii::Vector<double> trial(x_);
    bool tangent_current = false;
    for (int escalation = 0;; ++escalation) {
      // Yamashita and Fukushima's mu ~ |R|: it damps the step where the residual is large and
      // vanishes with it, so that convergence stays quadratic, even when the tangent is
      // singular at the solution (a tube touching the body at zero tension).
      const double shift_N_per_m =
          std::max(shift_N_per_m_, parameters_.residual_shift_factor * residual_N / mean_edge_m_);
      try {
        if (escalation == 0) {
          // The tangent and residual at x_ are assembled: shift in place (same pattern).
          if (shift_N_per_m > 0.0) MatShift(tangent_.petsc_matrix(), shift_N_per_m);
          krylov_iterations.push_back(solve_linear_system(step, notes));
        } else {
          krylov_iterations.push_back(solve_shifted(step, shift_N_per_m, notes));
        }
      } catch (const SolverError&) {
        // A singular tangent the residual's shift is too small to lift (a loose, stress-free
        // garment whose midpoint nodes have no stiffness across it): shift as after a failed
        // line search.
        if (escalation >= 8) throw;
        linear_solver_->reset();  // a failed factorization is not reused
        shift_N_per_m_ =
            shift_N_per_m_ > 0.0 ? 10.0 * shift_N_per_m_ : 1e-2 * stiffness_scale_N_per_m;
        ++n_shifted_solves_;
        continue;
      }
      const dealii::Vector<double> increment = gather_increment();
      // A step longer than half an edge leaves the region where the linearisation holds (and
      // may carry the garment, which has no bending stiffness, into a folded state): shorten
      // it.
      double s = std::min(1.0, 0.5 * mean_edge_m_ / increment.linfty_norm());
      bool accepted = !parameters_.line_search;
      for (int halving = 0; parameters_.line_search; ++halving) {
        trial = x_;
        trial.add(s, increment);
        // Armijo's sufficient decrease (1e-4 s) of ||R||_2.
        tangent_current = halving == 0;
        assemble(trial, tangent_current);
        const double norm = rhs_.l2_norm();
        accepted = std::isfinite(norm) && norm <= (1.0 - 1e-4 * s) * norm_0;
        if (accepted || halving >= parameters_.max_line_search_halvings) break;
        s *= 0.5;
      }
      if (!parameters_.line_search) {
        trial = x_;
        trial.add(s, increment);
        tangent_current = false;
      }
      if (accepted) {
        shift_N_per_m_ = shift_N_per_m_ > 1e-8 * stiffness_scale_N_per_m ? 0.1 * shift_N_per_m_ : 0;
        break;
      }
      if (escalation >= 8) break;  // take the shortest step tried; the iteration limit judges
      shift_N_per_m_ =
          shift_N_per_m_ > 0.0 ? 10.0 * shift_N_per_m_ : 1e-2 * stiffness_scale_N_per_m;
      ++n_shifted_solves_;
    }
    x_ = trial;
    if (!tangent_current) assemble(x_, true);
  }
}

void FemBackend::Implementation::secant_predictor(const LoadStep& step) {
  if (n_history_ < 2) return;
  const double ratio = (step.alpha - history_alpha_[0]) / (history_alpha_[0] - history_alpha_[1]);
  // Only forward steps no longer than a few of the last: further out the secant misleads.
  if (!std::isfinite(ratio) || ratio <= 0.0 || ratio > 4.0) return;
  x_ = history_x_[0];
  x_.add(ratio, history_x_[0], -ratio, history_x_[1]);
  for (std::size_t w = 0; w < multiplier_N_.size(); ++w)
    multiplier_N_[w] =
        std::max(0.0, history_multiplier_N_[0][w] +
                          ratio * (history_multiplier_N_[0][w] - history_multiplier_N_[1][w]));
  // No constraints_.distribute(x_): the pins and held ends constrain increments, and the
  // secant of two states that satisfy them (and the seams) satisfies them already.
}

int FemBackend::Implementation::solve_shifted(const LoadStep& step, double shift_N_per_m,
                                              std::string& notes) {
  assemble(x_, true);
  // Same pattern (the diagonal is in it): the factorization's analysis is kept.
  MatShift(tangent_.petsc_matrix(), shift_N_per_m);
  return solve_linear_system(step, notes);
}

// Nodes the body has grown into, and those predicted in contact, start from their closest
// point on its surface: the predictor of a growing body, keeping held nodes on their planes.
void FemBackend::Implementation::contact_predictor() {
  for (int node = 0; node < n_nodes(); ++node) {
    const Vec3 x = node_position(x_, node);
    const SurfacePoint s = problem_.body->query(x);
    // Nodes in contact at the last step (the multiplier predicted positive) go onto the
    // surface too: a penetration or gap left by the secant would cost kA g of residual.
    if (s.signed_distance_m >= 0.0 && multiplier_N_[node] <= 0.0) continue;
    Vec3 target = s.closest_point_m;
    Vec3 move = target - x;
    node_constrained_.remove_constrained(node, move);
    target = x + move;
    set_node_position(x_, node, target);
  }
}

StepReport FemBackend::Implementation::solve(const LoadStep& step) {
  const auto start = std::chrono::steady_clock::now();
  StepReport report;
  report.tolerance_N = parameters_.residual_tolerance * force_scale_N_;
  history_N_.clear();
  // After a fallback, the solver asked for returns once the garment presses on the body: the
  // loose garment's tangent (singular at zero tension) is what defeats CG, and the first
  // contact step, where the tension starts from zero, is left to the solver that got there.
  if (had_contact_) linear_solver_->restore_requested();
  secant_predictor(step);
  contact_predictor();
  shift_N_per_m_ = 0.0;
  n_shifted_solves_ = 0;

  std::vector<int> krylov_iterations;
  std::string solver_notes;
  std::vector<std::string> rounds;
  bool gap_closed = false;
  int n_active = 0;
  for (int round = 0; round < parameters_.max_augmented_lagrangian_iterations; ++round) {
    const std::size_t first = history_N_.size();
    report.iterations += newton(step, krylov_iterations, solver_notes);
    rounds.push_back(
        format_list(std::vector<double>(history_N_.begin() + first, history_N_.end())));
    // Uzawa's update: the multiplier becomes the contact force just found (nodal_contact.h).
    max_penetration_m_ = 0.0;
    n_active = 0;
    for (int node = 0; node < n_nodes(); ++node) {
      const NodalContact c = nodal_contact(*problem_.body, node_position(x_, node),
                                           multiplier_N_[node], penalty_N_per_m_[node], 0.0);
      multiplier_N_[node] = c.multiplier_N;
      if (c.multiplier_N > 0.0) {
        ++n_active;
        max_penetration_m_ = std::max(max_penetration_m_, std::abs(c.gap_m));
      }
    }
    if (max_penetration_m_ <= parameters_.gap_tolerance_m) {
      gap_closed = true;
      break;
    }
  }
  report.residual_N = history_N_.empty() ? 0.0 : history_N_.back();
  if (!gap_closed)
    fail(step,
         "the contact gap did not close (largest penetration " +
             std::to_string(max_penetration_m_) + " m) after " +
             std::to_string(parameters_.max_augmented_lagrangian_iterations) +
             " augmented-Lagrangian updates",
         report.residual_N);
  if (had_contact_ && n_active == 0) fail(step, "contact lost", report.residual_N);
  had_contact_ = had_contact_ || n_active > 0;
  if (n_active == 0) {
    n_history_ = 0;
  } else {
    history_alpha_[1] = history_alpha_[0];
    history_x_[1].swap(history_x_[0]);
    history_multiplier_N_[1].swap(history_multiplier_N_[0]);
    history_alpha_[0] = step.alpha;
    history_x_[0] = x_;
    history_multiplier_N_[0] = multiplier_N_;
    n_history_ = std::min(n_history_ + 1, 2);
  }
  update_state();

  std::ostringstream detail;
  detail << "newton " << report.iterations << " in " << rounds.size() << " AL rounds, |R|_max N: ";
  for (std::size_t r = 0; r < rounds.size(); ++r)
    detail << (r ? " | " : "") << "[" << rounds[r] << "]";
  detail << "; krylov (" << to_string(linear_solver_->kind()) << "):";
  for (int k : krylov_iterations) detail << " " << k;
  if (!solver_notes.empty()) detail << " [" << solver_notes << "]";
  if (n_shifted_solves_ > 0) detail << "; " << n_shifted_solves_ << " shifted tangents";
  detail << "; max gap " << max_penetration_m_ << " m; " << n_active << " in contact";
  if (parameters_.element_degree != 1)
    detail << "; vertex forces are the recovered traction (degree " << parameters_.element_degree
           << ")";
  report.detail = detail.str();
  report.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

std::vector<Vec3> FemBackend::Implementation::internal_force_N(
    const dealii::Vector<double>& x) const {
  dealii::Vector<double> gradient_full(dof_handler_.n_dofs());
  Eigen::VectorXd gradient;
  for (unsigned int cell = 0; cell < cell_dofs_.size(); ++cell) {
    if (!cell_owned_[cell]) continue;
    cell_kernel(cell, x, gradient, nullptr);
    for (unsigned int i = 0; i < cell_dofs_[cell].size(); ++i)
      gradient_full[cell_dofs_[cell][i]] += gradient[3 * local_node_[i] + local_component_[i]];
  }
  MPI_Allreduce(MPI_IN_PLACE, gradient_full.begin(), static_cast<int>(gradient_full.size()),
                MPI_DOUBLE, MPI_SUM, comm_);
  // The nodal force of a welded vertex sums its copies (the seam is one vertex).
  std::vector<Vec3> force(problem_.mesh->n_vertices, Vec3::Zero());
  for (int u = 0; u < problem_.mesh->n_unwelded_vertices(); ++u)
    force[problem_.mesh->welded_index[u]] -= vertex_position(gradient_full, u);
  return force;
}

void FemBackend::Implementation::update_state() {
  const SimulationMesh& mesh = *problem_.mesh;
  const int n = mesh.n_vertices;
  state_.positions_m.resize(n);
  for (int w = 0; w < n; ++w) state_.positions_m[w] = vertex_position(x_, master_[w]);
  if (parameters_.element_degree != 1) {
    update_state_from_recovered_traction();
    return;
  }
  state_.internal_force_N = internal_force_N(x_);
  state_.contact_force_N.assign(n, Vec3::Zero());
  state_.in_contact.assign(n, 0);
  state_.gap_m.assign(n, 0.0);
  const std::vector<double> area =
      vertex_areas(mesh.triangles, state_.positions_m, n, VertexAreaDefinition::barycentric);
  traction_Pa_.assign(n, 0.0);
  for (int w = 0; w < n; ++w) {
    const SurfacePoint s = problem_.body->query(state_.positions_m[w]);
    state_.gap_m[w] = s.signed_distance_m;
    if (multiplier_N_[w] <= 0.0) continue;
    state_.in_contact[w] = 1;
    state_.contact_force_N[w] = multiplier_N_[w] * s.outward_normal;
    if (area[w] > 0.0) traction_Pa_[w] = multiplier_N_[w] / area[w];
  }
}

// Quadratic elements carry a consistent load int N_k p dA at each node: about nothing at the
// corners and A/3 at the midpoints under a uniform pressure, so their nodal forces over
// vertex areas do not read a pressure. Worse, the corners' share is of either sign and
// contact cannot pull: on a cylinder the corners float a little off the body (by about h^4)
// and only the midpoints press. The traction is therefore recovered in the linear functions
// on the current (curved) surface, whose loads the nodal forces determine: the hat of vertex w is
// phi_w = N_w + 1/2 sum_e N_e over its edges e (a quadratic function), so int phi_w t dA = f_w +
// 1/2 sum_e f_e, and the L2 projection M t = f of traction_recovery.h (M_vw = int phi_v phi_w dA)
// returns the vertex tractions; it shares each midpoint's force between its edge's ends. Each
// welded vertex is then handed the force the shared extractor turns back into it:
//   internal_force_N = -(t A_v) n_v,  contact_force_N = t A_v n_body,
// with A_v the flat barycentric area and n_v the vertex normal the extractor computes (oriented
// away from the body), so that p_v = -(f . n_v) / A_v = t exactly, and a uniform pressure reads
// its value at every vertex.
void FemBackend::Implementation::update_state_from_recovered_traction() {
  const SimulationMesh& mesh = *problem_.mesh;
  const int n = mesh.n_vertices;
  SurfaceQuadrature quadrature;
  quadrature.shape_values = hat_values_;
  for (const auto& v : cell_vertices_) quadrature.cell_nodes.emplace_back(v.begin(), v.end());
  quadrature.point_area_m2.assign(cell_dofs_.size(), {});
  const unsigned int n_local = fe_.n_dofs_per_cell();
  const unsigned int n_element_nodes = n_local / 3;
  for (unsigned int cell = 0; cell < cell_dofs_.size(); ++cell)
    for (unsigned int q = 0; q < cell_JxW_m2_[cell].size(); ++q) {
      // dA = |x,1 x x,2| dA_grain, x,i the columns of F = dx/dX_grain.
      Mat32 F = Mat32::Zero();
      for (unsigned int i = 0; i < n_local; ++i)
        F.row(local_component_[i]) +=
            x_[cell_dofs_[cell][i]] *
            cell_grad_grain_[cell][q * n_element_nodes + local_node_[i]].transpose();
      const double grain_area_m2 = cell_JxW_m2_[cell][q] * cell_grain_area_ratio_[cell];
      quadrature.point_area_m2[cell].push_back(Vec3(F.col(0)).cross(Vec3(F.col(1))).norm() *
                                               grain_area_m2);
    }
  std::vector<double> hat_load_N(n, 0.0);
  for (int w = 0; w < n; ++w) hat_load_N[w] = std::max(0.0, multiplier_N_[w]);
  for (std::size_t e = 0; e < edge_ends_.size(); ++e)
    for (int w : edge_ends_[e]) hat_load_N[w] += 0.5 * std::max(0.0, multiplier_N_[n + e]);
  const std::vector<double> traction = recover_traction_Pa(n, quadrature, hat_load_N);

  // A vertex touches the body where its own node or a midpoint of one of its edges does.
  std::vector<char> touching(n, 0);
  for (int w = 0; w < n; ++w) touching[w] = multiplier_N_[w] > 0.0;
  for (std::size_t e = 0; e < edge_ends_.size(); ++e)
    if (multiplier_N_[n + e] > 0.0) touching[edge_ends_[e][0]] = touching[edge_ends_[e][1]] = 1;

  const std::vector<double> area =
      vertex_areas(mesh.triangles, state_.positions_m, n, VertexAreaDefinition::barycentric);
  const std::vector<Vec3> normal = vertex_normals(mesh.triangles, state_.positions_m, n);
  state_.internal_force_N.assign(n, Vec3::Zero());
  state_.contact_force_N.assign(n, Vec3::Zero());
  state_.in_contact.assign(n, 0);
  state_.gap_m.assign(n, 0.0);
  traction_Pa_.assign(n, 0.0);
  for (int w = 0; w < n; ++w) {
    const SurfacePoint s = problem_.body->query(state_.positions_m[w]);
    state_.gap_m[w] = s.signed_distance_m;
    if (!touching[w]) continue;
    const Vec3 n_v = normal[w].dot(s.outward_normal) < 0.0 ? Vec3(-normal[w]) : normal[w];
    state_.in_contact[w] = 1;
    traction_Pa_[w] = traction[w];
    state_.internal_force_N[w] = -(traction[w] * area[w]) * n_v;
    state_.contact_force_N[w] = traction[w] * area[w] * s.outward_normal;
  }
}

std::vector<Vec3> FemBackend::Implementation::node_positions(
    const std::vector<Vec3>& vertex_positions_m) const {
  const dealii::Vector<double> x = dof_positions(vertex_positions_m);
  std::vector<Vec3> nodes(n_nodes());
  for (int node = 0; node < n_nodes(); ++node) nodes[node] = node_position(x, node);
  return nodes;
}

void FemBackend::Implementation::linearise(const std::vector<Vec3>& node_positions_m,
                                           Eigen::VectorXd& residual_N,
                                           Eigen::MatrixXd& tangent_N_per_m) const {
  if (static_cast<int>(node_positions_m.size()) != n_nodes())
    throw std::invalid_argument("fem backend: linearise() needs one position per node");
  dealii::Vector<double> x(dof_handler_.n_dofs());
  // DoF -> row 3 node + c of the node it carries (every copy of a node shares its rows).
  std::vector<int> dof_row(dof_handler_.n_dofs(), -1);
  for (int node = 0; node < n_nodes(); ++node) {
    set_node_position(x, node, node_positions_m[node]);
    for (const DofTriple& d : node_copies_[node])
      for (int c = 0; c < 3; ++c) dof_row[d[c]] = 3 * node + c;
  }
  const int n = n_nodes();
  residual_N.setZero(3 * n);
  tangent_N_per_m.setZero(3 * n, 3 * n);
  Eigen::VectorXd gradient;
  Eigen::MatrixXd hessian;
  const unsigned int n_local = fe_.n_dofs_per_cell();
  std::vector<int> row(n_local);
  for (unsigned int cell = 0; cell < cell_dofs_.size(); ++cell) {
    cell_kernel(cell, x, gradient, &hessian);
    for (unsigned int i = 0; i < n_local; ++i) row[i] = dof_row[cell_dofs_[cell][i]];
    for (unsigned int i = 0; i < n_local; ++i) {
      const int a = 3 * local_node_[i] + local_component_[i];
      residual_N[row[i]] += gradient[a];
      for (unsigned int j = 0; j < n_local; ++j)
        tangent_N_per_m(row[i], row[j]) += hessian(a, 3 * local_node_[j] + local_component_[j]);
    }
  }
  for (int node = 0; node < n; ++node) {
    const NodalContact c =
        nodal_contact(*problem_.body, node_positions_m[node], multiplier_N_[node],
                      penalty_N_per_m_[node], normal_step_m_);
    residual_N.segment<3>(3 * node) -= c.force_N;
    tangent_N_per_m.block<3, 3>(3 * node, 3 * node) += c.stiffness_N_per_m;
  }
}

FemBackend::FemBackend(const Problem& problem, const FemParameters& parameters) {
  start_mpi_and_petsc();
  impl_ = std::make_unique<Implementation>(problem, parameters);
}

FemBackend::~FemBackend() = default;

void FemBackend::set_positions(const std::vector<Vec3>& positions_m) {
  impl_->set_positions(positions_m);
}

StepReport FemBackend::solve(const LoadStep& step) {
  return impl_->solve(step);
}

SurfaceState FemBackend::state() const {
  return impl_->state_;
}

std::vector<std::pair<std::string, std::vector<double>>> FemBackend::extra_point_data() const {
  return {{"contact_traction_Pa", impl_->traction_Pa_}};
}

std::vector<double> FemBackend::contact_traction_Pa() const {
  return impl_->traction_Pa_;
}

const std::vector<double>& FemBackend::nodal_contact_force_N() const {
  return impl_->multipliers_N();
}

double FemBackend::max_penetration_m() const {
  return impl_->max_penetration_m_;
}

const std::vector<double>& FemBackend::last_residual_history_N() const {
  return impl_->history_N_;
}

void FemBackend::linearise(const std::vector<Vec3>& node_positions_m, Eigen::VectorXd& residual_N,
                           Eigen::MatrixXd& tangent_N_per_m) const {
  impl_->linearise(node_positions_m, residual_N, tangent_N_per_m);
}

std::vector<Vec3> FemBackend::node_positions(const std::vector<Vec3>& vertex_positions_m) const {
  return impl_->node_positions(vertex_positions_m);
}

std::vector<Vec3> FemBackend::internal_force_N(const std::vector<Vec3>& positions_m) const {
  return impl_->internal_force_N(impl_->dof_positions(positions_m));
}

}  // namespace tightfit
