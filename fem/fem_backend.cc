// The finite-element membrane backend: mesh, degrees of freedom, constraints, assembly,
// PETSc solves and Newton's method with augmented-Lagrangian contact. The one translation
// unit of the backend that includes deal.II's finite-element and PETSc headers.
#include "fem/fem_backend.h"

#include "contact/cylinder.h"
#include "core/mesh_geometry.h"
#include "fem/membrane_kernel.h"
#include "fem/nodal_contact.h"
#include "fem/petsc_linear_solver.h"

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

  void linearise(const std::vector<Vec3>& positions_m, Eigen::VectorXd& residual_N,
                 Eigen::MatrixXd& tangent_N_per_m) const;
  std::vector<Vec3> internal_force_N(const dealii::Vector<double>& x) const;
  dealii::Vector<double> dof_positions(const std::vector<Vec3>& positions_m) const;

  SurfaceState state_;
  std::vector<double> traction_Pa_;
  std::vector<double> history_N_;
  double max_penetration_m_ = 0.0;

 private:
  void build_mesh();
  // Shape-function gradients in grain axes and JxW at every quadrature point of every cell:
  // they live on the reference (pattern) configuration, so they are computed once.
  void build_cell_quadrature();
  void build_constraints_and_matrix();
  Vec3 vertex_position(const dealii::Vector<double>& x, int unwelded) const;
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
  // DoF -> row 3 w + c of the welded vertex w it carries (component c); -1 off vertices.
  std::vector<int> dof_vertex_row_;

  dealii::AffineConstraints<double> constraints_;
  dealii::PETScWrappers::MPI::SparseMatrix tangent_;
  dealii::PETScWrappers::MPI::Vector rhs_, increment_;
  std::unique_ptr<PetscLinearSolver> linear_solver_;
  dealii::Vector<double> x_;  // every DoF on every rank: the current positions, m

  std::vector<double> penalty_N_per_m_;  // k A0 per welded vertex
  std::vector<double> multiplier_N_;     // augmented-Lagrangian estimate per welded vertex
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
      quadrature_(parameters.element_degree),
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
  dof_vertex_row_.assign(dof_handler_.n_dofs(), -1);
  for (int u = 0; u < mesh.n_unwelded_vertices(); ++u)
    for (int c = 0; c < 3; ++c) dof_vertex_row_[vertex_dofs_[u][c]] = 3 * mesh.welded_index[u] + c;
  build_cell_quadrature();
  linear_solver_ = std::make_unique<PetscLinearSolver>(parameters.linear_solver,
                                                       parameters.max_linear_iterations, comm_);

  // Penalty k = beta Y / h^2 (Pa/m) times the barycentric rest area of each vertex.
  double edge_sum = 0.0;
  for (const auto& r : mesh.rest_triangles)
    edge_sum += (r[1] - r[0]).norm() + (r[2] - r[1]).norm() + (r[0] - r[2]).norm();
  mean_edge_m_ = edge_sum / (3.0 * mesh.rest_triangles.size());
  force_scale_N_ = problem.law->stiffness_scale() * mean_edge_m_;
  normal_step_m_ = 1e-6 * mean_edge_m_;
  const double k_Pa_per_m =
      parameters.penalty_factor * problem.law->stiffness_scale() / (mean_edge_m_ * mean_edge_m_);
  const std::vector<double> areas = rest_triangle_areas(mesh);
  penalty_N_per_m_.assign(mesh.n_vertices, 0.0);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) penalty_N_per_m_[mesh.triangles[t][k]] += k_Pa_per_m * areas[t] / 3;
  multiplier_N_.assign(mesh.n_vertices, 0.0);

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

void FemBackend::Implementation::build_cell_quadrature() {
  dealii::FEValues<2> fe_values(mapping_, fe_, quadrature_,
                                dealii::update_gradients | dealii::update_JxW_values);
  const unsigned int n_cells = triangulation_.n_active_cells();
  const unsigned int n_local = fe_.n_dofs_per_cell();
  const unsigned int n_nodes = n_local / 3;
  cell_dofs_.assign(n_cells, std::vector<global_dof_index>(n_local));
  cell_JxW_m2_.assign(n_cells, {});
  cell_grad_grain_.assign(n_cells, {});
  cell_owned_.assign(n_cells, 0);
  for (const auto& cell : dof_handler_.active_cell_iterators()) {
    const unsigned int c = cell->active_cell_index();
    fe_values.reinit(cell);
    cell->get_dof_indices(cell_dofs_[c]);
    cell_owned_[c] = cell->is_locally_owned();
    const Mat2& G = to_grain_gradient_[c];
    cell_grad_grain_[c].resize(quadrature_.size() * n_nodes);
    for (unsigned int q = 0; q < quadrature_.size(); ++q) {
      cell_JxW_m2_[c].push_back(fe_values.JxW(q));
      for (unsigned int i = 0; i < n_local; ++i) {
        if (local_component_[i] != 0) continue;
        const dealii::Tensor<1, 2> g = fe_values.shape_grad(i, q);
        cell_grad_grain_[c][q * n_nodes + local_node_[i]] = G * Vec2(g[0], g[1]);
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
  dealii::Vector<double> x(dof_handler_.n_dofs());
  for (int u = 0; u < problem_.mesh->n_unwelded_vertices(); ++u)
    for (int c = 0; c < 3; ++c)
      x[vertex_dofs_[u][c]] = positions_m[problem_.mesh->welded_index[u]][c];
  return x;
}

Vec3 FemBackend::Implementation::vertex_position(const dealii::Vector<double>& x,
                                                 int unwelded) const {
  const DofTriple& d = vertex_dofs_[unwelded];
  return Vec3(x[d[0]], x[d[1]], x[d[2]]);
}

void FemBackend::Implementation::build_constraints_and_matrix() {
  const SimulationMesh& mesh = *problem_.mesh;
  constraints_.clear();
  // Seams: every copy of a welded vertex follows the copy that carries it.
  for (int u = 0; u < mesh.n_unwelded_vertices(); ++u) {
    const int m = master_[mesh.welded_index[u]];
    if (m == u) continue;
    for (int c = 0; c < 3; ++c) {
      constraints_.add_line(vertex_dofs_[u][c]);
      constraints_.add_entry(vertex_dofs_[u][c], vertex_dofs_[m][c], 1.0);
    }
  }
  // Held ends: the end vertices keep their coordinate along held_direction.
  std::vector<char> held(mesh.n_vertices, 0);
  if (problem_.end_condition == EndCondition::held_ends)
    for (int w : problem_.held_vertices) {
      held[w] = 1;
      constrain_directions(vertex_dofs_[master_[w]], {problem_.held_direction.normalized()},
                           constraints_);
    }
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
      if (!held[w] && radial > 1e-12 && distance < best - 1e-12) {
        best = distance;
        pinned = w;
      }
    }
    if (pinned >= 0) {
      const Vec3 r = vertex_position(x_, master_[pinned]) - origin;
      std::vector<Vec3> directions{axis.cross(r).normalized()};
      if (problem_.end_condition == EndCondition::free_ends) directions.push_back(axis);
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
  const unsigned int n_nodes = n_local / 3;
  const std::vector<global_dof_index>& dofs = cell_dofs_[cell];
  gradient.setZero(n_local);
  if (hessian) hessian->setZero(n_local, n_local);
  std::vector<Vec2> grad_grain(n_nodes);
  for (unsigned int q = 0; q < cell_JxW_m2_[cell].size(); ++q) {
    std::copy_n(cell_grad_grain_[cell].begin() + q * n_nodes, n_nodes, grad_grain.begin());
    // F = dx/dX_grain = sum_a x_a grad_N_a^T (architecture.md: the membrane's 3x2 gradient).
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

  // Contact at the vertices, each on the rank that owns its DoFs.
  dealii::FullMatrix<double> vertex_matrix(3, 3);
  dealii::Vector<double> vertex_rhs(3);
  std::vector<global_dof_index> vertex_dof_list(3);
  for (int w = 0; w < problem_.mesh->n_vertices; ++w) {
    const DofTriple& d = vertex_dofs_[master_[w]];
    if (!owned_dofs_.is_element(d[0])) continue;
    const NodalContact c =
        nodal_contact(*problem_.body, vertex_position(x, master_[w]), multiplier_N_[w],
                      penalty_N_per_m_[w], with_tangent ? normal_step_m_ : 0.0);
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
      if (escalation == 0) {
        // The tangent and residual at x_ are assembled: shift in place (same pattern).
        if (shift_N_per_m > 0.0) MatShift(tangent_.petsc_matrix(), shift_N_per_m);
        krylov_iterations.push_back(solve_linear_system(step, notes));
      } else {
        krylov_iterations.push_back(solve_shifted(step, shift_N_per_m, notes));
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

// Vertices the body has grown into, and those predicted in contact, start from their closest
// point on its surface: the predictor of a growing body, keeping held vertices on their planes.
void FemBackend::Implementation::contact_predictor() {
  const SimulationMesh& mesh = *problem_.mesh;
  std::vector<char> held(mesh.n_vertices, 0);
  if (problem_.end_condition == EndCondition::held_ends)
    for (int w : problem_.held_vertices) held[w] = 1;
  const Vec3 d = problem_.held_direction.normalized();
  std::vector<Vec3> moved(mesh.n_vertices);
  std::vector<char> move(mesh.n_vertices, 0);
  for (int w = 0; w < mesh.n_vertices; ++w) {
    const Vec3 x = vertex_position(x_, master_[w]);
    const SurfacePoint s = problem_.body->query(x);
    // Vertices in contact at the last step (the multiplier predicted positive) go onto the
    // surface too: a penetration or gap left by the secant would cost kA g of residual.
    if (s.signed_distance_m >= 0.0 && multiplier_N_[w] <= 0.0) continue;
    Vec3 target = s.closest_point_m;
    if (held[w]) target -= (target - x).dot(d) * d;
    moved[w] = target;
    move[w] = 1;
  }
  for (int u = 0; u < mesh.n_unwelded_vertices(); ++u) {
    const int w = mesh.welded_index[u];
    if (move[w])
      for (int c = 0; c < 3; ++c) x_[vertex_dofs_[u][c]] = moved[w][c];
  }
}

StepReport FemBackend::Implementation::solve(const LoadStep& step) {
  const auto start = std::chrono::steady_clock::now();
  StepReport report;
  report.tolerance_N = parameters_.residual_tolerance * force_scale_N_;
  history_N_.clear();
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
    for (int w = 0; w < problem_.mesh->n_vertices; ++w) {
      const NodalContact c = nodal_contact(*problem_.body, vertex_position(x_, master_[w]),
                                           multiplier_N_[w], penalty_N_per_m_[w], 0.0);
      multiplier_N_[w] = c.multiplier_N;
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

  report.converged = true;
  std::ostringstream detail;
  detail << "newton " << report.iterations << " in " << rounds.size() << " AL rounds, |R|_max N: ";
  for (std::size_t r = 0; r < rounds.size(); ++r)
    detail << (r ? " | " : "") << "[" << rounds[r] << "]";
  detail << "; krylov (" << to_string(linear_solver_->kind()) << "):";
  for (int k : krylov_iterations) detail << " " << k;
  if (!solver_notes.empty()) detail << " [" << solver_notes << "]";
  if (n_shifted_solves_ > 0) detail << "; " << n_shifted_solves_ << " shifted tangents";
  detail << "; max gap " << max_penetration_m_ << " m; " << n_active << " in contact";
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

void FemBackend::Implementation::linearise(const std::vector<Vec3>& positions_m,
                                           Eigen::VectorXd& residual_N,
                                           Eigen::MatrixXd& tangent_N_per_m) const {
  const SimulationMesh& mesh = *problem_.mesh;
  const int n = mesh.n_vertices;
  const dealii::Vector<double> x = dof_positions(positions_m);
  residual_N.setZero(3 * n);
  tangent_N_per_m.setZero(3 * n, 3 * n);
  Eigen::VectorXd gradient;
  Eigen::MatrixXd hessian;
  const unsigned int n_local = fe_.n_dofs_per_cell();
  std::vector<int> row(n_local);
  for (unsigned int cell = 0; cell < cell_dofs_.size(); ++cell) {
    cell_kernel(cell, x, gradient, &hessian);
    // Linear elements: every DoF of a cell sits on a vertex, the row of its welded vertex.
    for (unsigned int i = 0; i < n_local; ++i) row[i] = dof_vertex_row_[cell_dofs_[cell][i]];
    for (unsigned int i = 0; i < n_local; ++i) {
      const int a = 3 * local_node_[i] + local_component_[i];
      residual_N[row[i]] += gradient[a];
      for (unsigned int j = 0; j < n_local; ++j)
        tangent_N_per_m(row[i], row[j]) += hessian(a, 3 * local_node_[j] + local_component_[j]);
    }
  }
  for (int w = 0; w < n; ++w) {
    const NodalContact c = nodal_contact(*problem_.body, positions_m[w], multiplier_N_[w],
                                         penalty_N_per_m_[w], normal_step_m_);
    residual_N.segment<3>(3 * w) -= c.force_N;
    tangent_N_per_m.block<3, 3>(3 * w, 3 * w) += c.stiffness_N_per_m;
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

double FemBackend::max_penetration_m() const {
  return impl_->max_penetration_m_;
}

const std::vector<double>& FemBackend::last_residual_history_N() const {
  return impl_->history_N_;
}

void FemBackend::linearise(const std::vector<Vec3>& positions_m, Eigen::VectorXd& residual_N,
                           Eigen::MatrixXd& tangent_N_per_m) const {
  impl_->linearise(positions_m, residual_N, tangent_N_per_m);
}

std::vector<Vec3> FemBackend::internal_force_N(const std::vector<Vec3>& positions_m) const {
  return impl_->internal_force_N(impl_->dof_positions(positions_m));
}

}  // namespace tightfit
