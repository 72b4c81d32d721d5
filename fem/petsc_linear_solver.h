// The Newton systems' PETSc solver, kept alive across Newton iterations, augmented-Lagrangian
// rounds and load steps. Plain PETSc (no deal.II): the matrix and vectors are handed over as
// PETSc handles.
//
// Reuse: the KSP keeps its operator. When the matrix keeps its nonzero pattern (the tangent's
// pattern is fixed once the constraints are), PCSetUp sees SAME_NONZERO_PATTERN and MUMPS
// redoes only the numerical factorization; the ordering and symbolic analysis of the first
// solve are kept.
//
// Fallback: conjugate gradients need a symmetric positive definite tangent. When CG reports an
// indefinite matrix or preconditioner, or stops without converging, the system is solved again
// by GMRES with the same BoomerAMG, and the solver stays with GMRES; when GMRES fails too, by
// MUMPS (GAMG's CG likewise to GMRES with GAMG). Each switch is recorded in `note` of the result
// that made it. restore_requested() returns to the solver asked for: the tangent that defeated CG
// (a loose garment's, singular at zero tension) does not last once the garment is in contact
// (FemBackend calls it then).

#pragma once

#include "fem/fem_parameters.h"

#include <petscksp.h>

#include <string>

namespace tightfit {

// Sets PETSc's process-wide options for `memory` (fem_parameters.h): with 'lean', GAMG's
// Galerkin products P^T A P by the all-at-once algorithm (-matptap_via allatonce: each row of
// the product formed and sent without storing A P, whose transient was the largest part of the
// hierarchy's setup) and GMRES restarted after 30 iterations (-fem_ksp_gmres_restart 30: its
// basis is the solve's largest single item). Options the user set (PETSC_OPTIONS) are kept;
// those set here for 'lean' are removed again for 'fast'. Call with PETSc started, before the
// solvers are configured.
void select_iterative_solver_memory(IterativeSolverMemory memory);

struct LinearSolveResult {
  int iterations = 0;  // Krylov iterations (0 for the direct solve)
  LinearSolverKind used = LinearSolverKind::direct;
  std::string note;  // why the solver switched, empty otherwise
};

class PetscLinearSolver {
 public:
  PetscLinearSolver(LinearSolverKind kind, int max_iterations, MPI_Comm comm);
  ~PetscLinearSolver();
  PetscLinearSolver(const PetscLinearSolver&) = delete;
  PetscLinearSolver& operator=(const PetscLinearSolver&) = delete;

  // Solves A x = b to ||b - A x|| <= relative_tolerance ||b|| (Krylov methods; the direct
  // solve is exact); throws std::runtime_error when every solver in the chain fails.
  // `node_coordinates` (laid out as b, each node's x, y, z in three consecutive rows; may be
  // null) gives GAMG the rigid motions as near null space and A a block size of 3; only
  // needs_node_coordinates() asks for them.
  LinearSolveResult solve(Mat A, Vec b, Vec x, double relative_tolerance,
                          Vec node_coordinates = nullptr);
  bool needs_node_coordinates() const { return uses_gamg(kind_); }
  // Forgets the factorization and preconditioner (call when the matrix's pattern changes).
  void reset();
  LinearSolverKind kind() const { return kind_; }
  // Back to the solver given to the constructor after a fallback (no-op otherwise).
  void restore_requested();

 private:
  void configure();
  // Returns true when the KSP converged; `iterations` and `reason` describe the attempt.
  bool attempt(Mat A, Vec b, Vec x, int& iterations, std::string& reason);

  LinearSolverKind requested_;
  LinearSolverKind kind_;
  int max_iterations_;
  MPI_Comm comm_;
  KSP ksp_ = nullptr;
};

}  // namespace tightfit
