// The finite-element backend's facade: it wires the reference mesh (reference_mesh.h), the
// constraints (fem_constraints.h), the assembly (membrane_assembly.h), Newton's method
// (newton_solver.h), the augmented-Lagrangian contact rounds (contact_rounds.h) and the
// post-processing (fem_state.h) behind the light fem_backend.h.
#include "fem/fem_backend.h"

#include "contact/nodal_contact.h"
#include "core/load_step_report.h"
#include "core/tension_scale.h"
#include "fem/contact_rounds.h"
#include "fem/fem_constraints.h"
#include "fem/fem_state.h"
#include "fem/held_turn_system.h"
#include "fem/membrane_assembly.h"
#include "fem/mesh_part.h"
#include "fem/newton_solver.h"
#include "fem/petsc_linear_solver.h"
#include "fem/reference_mesh.h"

#include <deal.II/base/mpi.h>

#include <petscsys.h>

#include <algorithm>

namespace tightfit {

namespace {

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

const Problem& checked(const Problem& problem, const FemParameters& parameters) {
  // The mesh is checked on rank 0 by the pattern's setup (it may be null on the others).
  if (!problem.law || !problem.body)
    throw std::invalid_argument("fem backend: the problem needs a mesh, a law and a body");
  if (problem.friction_coefficient > 0.0) {
    // Friction's tangent is unsymmetric (contact/coulomb_friction.h): CG cannot take it.
    if (uses_cg(parameters.linear_solver))
      throw std::invalid_argument(
          "Finite elements/Linear solver = " + std::string(to_string(parameters.linear_solver)) +
          ": Contact/Friction coefficient > 0 makes the tangent unsymmetric; use direct (MUMPS "
          "LU), gmres-amg or gmres-gamg");
  }
  return problem;
}

// The problem with its law relaxed as Finite elements/Slack treatment asks; `relaxed` keeps
// the relaxed law alive.
Problem with_slack_treatment(const Problem& problem, const FemParameters& parameters,
                             std::unique_ptr<MaterialLaw>& relaxed) {
  if (parameters.slack_treatment == SlackTreatment::none) return problem;
  if (!problem.fabric)
    throw std::invalid_argument(
        "Finite elements/Slack treatment = " + std::string(to_string(parameters.slack_treatment)) +
        ": the problem has no fabric to relax");
  try {
    relaxed = make_tension_field_law(problem.law->name(), *problem.fabric,
                                     parameters.compression_stiffness_fraction);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("Finite elements/Slack treatment = tension field: " +
                                std::string(e.what()));
  }
  Problem result = problem;
  result.law = relaxed.get();
  return result;
}

// Contact set predictions = auto: with friction, every Newton step is solved once more on the
// stick-slip and contact sides it predicts (the tops' steps from the mass-spring state took 43
// Newton iterations so, and crept past 90 on the sides at x: docs/performance-bodies.md, "Newton
// on the tops"); without, none beyond the globalization's own (newton_solver.h).
FemParameters with_frictional_predictions(const Problem& problem, FemParameters parameters) {
  if (parameters.max_contact_set_predictions == FemParameters::kAutoPredictions)
    parameters.max_contact_set_predictions = problem.friction_coefficient > 0.0 ? 1 : 0;
  return parameters;
}

}  // namespace

class FemBackend::Implementation {
 public:
  Implementation(const Problem& problem, const FemParameters& parameters)
      : problem_(with_slack_treatment(checked(problem, parameters), parameters, relaxed_law_)),
        parameters_(with_frictional_predictions(problem, parameters)),
        pattern_(problem_, parameters.element_degree, comm_),
        // The exact (unsymmetric) contact tangent unless CG solves the systems.
        assembly_(pattern_, problem_, uses_cg(parameters.linear_solver), comm_),
        newton_(pattern_, parameters_, problem.law->stiffness_scale(),
                tension_scale_N(pattern_.mean_rest_edge_m(), pattern_.rest_area_m2(),
                                problem.law->stiffness_scale()),
                problem.body, comm_),
        contact_(pattern_, problem_, parameters),
        held_turn_(pattern_, uses_cg(parameters.linear_solver)) {
    // Every vertex held along one direction: the mean turn about it is held too
    // (held_turn_system.h).
    newton_.set_held_turn(&held_turn_);
    // Frictionless, a step the line search cut is solved once more on the contact set it
    // predicts (docs/backends.md, "Newton's line search"); with friction every step is
    // (with_frictional_predictions).
    newton_.set_contact_set_predictor([this](const DofVector& x, const DofVector* increment) {
      return contact_.predict_contact_set(x, increment);
    });
    // Start flat in the layout plane until the caller places the garment.
    set_positions(layout_start_on_every_rank(problem.mesh, pattern_.n_vertices(), comm_));
  }

  void set_positions(const std::vector<Vec3>& positions_m) {
    if (static_cast<int>(positions_m.size()) != pattern_.n_vertices())
      throw std::invalid_argument("fem backend: set_positions needs one position per vertex");
    x_ = pattern_.dof_positions(positions_m);
    contact_.start_from(x_);
    build_constraints_and_system(pattern_, problem_, positions_m, comm_, system_);
    // A new matrix: its pattern may differ, so the next solve analyses it afresh.
    newton_.pattern_changed();
  }

  StepReport solve(const LoadStep& step);

  std::unique_ptr<MaterialLaw> relaxed_law_;  // the law of problem_ under a slack treatment
  Problem problem_;
  FemParameters parameters_;
  MPI_Comm comm_ = MPI_COMM_WORLD;
  ReferenceMesh pattern_;
  MembraneAssembly assembly_;
  NewtonSolver newton_;
  ContactRounds contact_;
  HeldTurnSystem held_turn_;
  NewtonSystem system_;
  DofVector x_;                // this rank's DoFs and ghosts: the current positions, m
  OwnedSurfaceOutput output_;  // of the last step, this rank's vertices only
  NewtonLog log_;              // of the last step, kept after a failure
};

StepReport FemBackend::Implementation::solve(const LoadStep& step) {
  const StepClock clock;  // this rank's CPU time
  StepReport report;
  write_step_header("fem", step, newton_.tolerance_N(), parameters_.stop.norm, report);
  NewtonLog& log = log_ = NewtonLog{};
  const NewtonSolver::Assembler assemble = [this, &step](const DofVector& x, bool with_tangent) {
    assembly_.assemble(x, contact_.nodes(), parameters_.tangent_shift_N_per_m, with_tangent,
                       step.gravity_on, system_);
    held_turn_.project_residual(x, with_tangent, system_);
  };
  newton_.set_energy(
      [this, &step](const DofVector& x) {
        return assembly_.energy_J(x, contact_.nodes(), step.gravity_on);
      },
      [this](const DofVector& x) { return assembly_.potential_defect_N(x, contact_.nodes()); });
  contact_.solve(step, newton_, assemble, system_, x_, log, report);
  newton_.set_energy({});
  report.residual_N = log.residual_N.empty() ? 0.0 : log.residual_N.back();
  output_ = OwnedSurfaceOutput(
      pattern_, surface_output(pattern_, assembly_, *problem_.body, x_,
                               pattern_.gather_nodes(contact_.nodes().multiplier_N),
                               step.gravity_on ? assembly_.gravity_load_N() : std::vector<Vec3>{},
                               pattern_.gather_nodes(contact_.friction_force_N())));

  report.has_newton = true;
  NewtonReport& newton = report.newton;
  newton.linear_solver = to_string(newton_.linear_solver().kind());
  newton.krylov_iterations = log.krylov_iterations;
  newton.linear_solver_switched = !log.notes.empty();
  // The globalization's switch shares the log line's bracket (core/step_report.cc).
  newton.linear_solver_notes = log.notes +
                               (!log.notes.empty() && !log.globalization.empty() ? "; " : "") +
                               log.globalization;
  newton.n_shifted_solves = log.n_shifted_solves;
  newton.n_set_predictions = log.n_set_predictions;
  newton.n_failed_line_searches = log.n_failed_line_searches;
  if (contact_.nodes().friction.active()) report.n_slipping = contact_.n_slipping();
  if (parameters_.element_degree != 1)
    report.note = "vertex forces are the recovered traction (degree " +
                  std::to_string(parameters_.element_degree) + ")";
  clock.read(report);
  return report;
}

FemBackend::FemBackend(const Problem& problem, const FemParameters& parameters) {
  start_mpi_and_petsc();
  select_iterative_solver_memory(parameters.iterative_solver_memory);
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
  return impl_->output_.state(impl_->pattern_);
}

std::vector<std::pair<std::string, std::vector<double>>> FemBackend::extra_point_data() const {
  return {{"contact_traction_Pa", contact_traction_Pa()}};
}

std::vector<double> FemBackend::contact_traction_Pa() const {
  return impl_->output_.contact_traction_Pa(impl_->pattern_);
}

std::vector<double> FemBackend::nodal_contact_force_N() const {
  return impl_->pattern_.gather_nodes(impl_->contact_.nodes().multiplier_N);
}

double FemBackend::max_penetration_m() const {
  return impl_->contact_.max_penetration_m();
}

const std::vector<double>& FemBackend::last_residual_history_N() const {
  return impl_->log_.residual_N;
}

void FemBackend::linearise(const std::vector<Vec3>& node_positions_m, Eigen::VectorXd& residual_N,
                           Eigen::MatrixXd& tangent_N_per_m) const {
  impl_->assembly_.linearise(node_positions_m, impl_->contact_.nodes(), residual_N,
                             tangent_N_per_m);
}

namespace {

// The DoF vector of every node at its position (serial: every copy of a seam node alike).
DofVector dofs_at_nodes(const ReferenceMesh& pattern, const std::vector<Vec3>& node_positions_m) {
  if (static_cast<int>(node_positions_m.size()) != pattern.n_nodes() ||
      pattern.n_owned_nodes() != pattern.n_nodes())
    throw std::invalid_argument(
        "fem backend: the potential for tests needs one position per node, on one MPI rank");
  DofVector x = pattern.dof_vector();
  for (int node = 0; node < pattern.n_nodes(); ++node)
    pattern.set_node_position(x, node, node_positions_m[node]);
  return x;
}

}  // namespace

double FemBackend::energy_J(const std::vector<Vec3>& node_positions_m, bool gravity_on) const {
  return impl_->assembly_.energy_J(dofs_at_nodes(impl_->pattern_, node_positions_m),
                                   impl_->contact_.nodes(), gravity_on);
}

double FemBackend::potential_defect_N(const std::vector<Vec3>& node_positions_m) const {
  return impl_->assembly_.potential_defect_N(dofs_at_nodes(impl_->pattern_, node_positions_m),
                                             impl_->contact_.nodes());
}

std::vector<Vec3> FemBackend::node_positions(const std::vector<Vec3>& vertex_positions_m) const {
  std::vector<Vec3> nodes = vertex_positions_m;
  for (const auto& ends : impl_->pattern_.edge_ends())
    nodes.push_back(0.5 * (vertex_positions_m[ends[0]] + vertex_positions_m[ends[1]]));
  return nodes;
}

std::vector<Vec3> FemBackend::gravity_load_N() const {
  return impl_->assembly_.gravity_load_N();
}

std::vector<Vec3> FemBackend::internal_force_N(const std::vector<Vec3>& positions_m) const {
  return impl_->assembly_.internal_force_N(impl_->pattern_.dof_positions(positions_m));
}

}  // namespace tightfit
