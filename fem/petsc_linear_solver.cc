#include "fem/petsc_linear_solver.h"

#include <array>
#include <stdexcept>

namespace tightfit {

namespace {

void check(PetscErrorCode code, const char* call) {
  if (code != 0) throw std::runtime_error(std::string("PETSc call failed: ") + call);
}

LinearSolverKind next_in_chain(LinearSolverKind kind) {
  switch (kind) {
    case LinearSolverKind::cg_amg:
      return LinearSolverKind::gmres_amg;
    case LinearSolverKind::cg_gamg:
      return LinearSolverKind::gmres_gamg;
    default:
      return LinearSolverKind::direct;
  }
}

// GAMG's near null space: the six rigid motions (three translations, three rotations about the
// origin) of the nodes at `coordinates` (x, y, z of each node in a row, as the DoFs are
// numbered), which the membrane's tangent maps to (about) nothing and which the coarse levels
// must represent. The matrix's rows are taken in blocks of three, one node each.
void set_rigid_motions(Mat A, Vec coordinates) {
  check(MatSetBlockSize(A, 3), "MatSetBlockSize");
  MatNullSpace rigid_motions;
  check(VecSetBlockSize(coordinates, 3), "VecSetBlockSize");
  check(MatNullSpaceCreateRigidBody(coordinates, &rigid_motions), "MatNullSpaceCreateRigidBody");
  check(MatSetNearNullSpace(A, rigid_motions), "MatSetNearNullSpace");
  check(MatNullSpaceDestroy(&rigid_motions), "MatNullSpaceDestroy");
}

}  // namespace

void select_iterative_solver_memory(IterativeSolverMemory memory) {
  struct Option {
    const char* name;
    const char* lean_value;
    bool set_here;
  };
  // PETSc's options are process-wide: remember which ones this function set.
  static std::array<Option, 2> options{
      {{"-matptap_via", "allatonce", false}, {"-fem_ksp_gmres_restart", "30", false}}};
  for (Option& option : options) {
    if (option.set_here) check(PetscOptionsClearValue(nullptr, option.name), "PetscOptionsClear");
    option.set_here = false;
    if (memory != IterativeSolverMemory::lean) continue;
    PetscBool user_set = PETSC_FALSE;
    check(PetscOptionsHasName(nullptr, nullptr, option.name, &user_set), "PetscOptionsHasName");
    if (user_set) continue;
    check(PetscOptionsSetValue(nullptr, option.name, option.lean_value), "PetscOptionsSetValue");
    option.set_here = true;
  }
}

PetscLinearSolver::PetscLinearSolver(LinearSolverKind kind, int max_iterations, MPI_Comm comm)
    : requested_(kind), kind_(kind), max_iterations_(max_iterations), comm_(comm) {}

void PetscLinearSolver::restore_requested() {
  if (kind_ == requested_) return;
  kind_ = requested_;
  reset();
}

PetscLinearSolver::~PetscLinearSolver() {
  reset();
}

void PetscLinearSolver::reset() {
  if (ksp_) KSPDestroy(&ksp_);
  ksp_ = nullptr;
}

void PetscLinearSolver::configure() {
  check(KSPCreate(comm_, &ksp_), "KSPCreate");
  PC pc;
  check(KSPGetPC(ksp_, &pc), "KSPGetPC");
  switch (kind_) {
    case LinearSolverKind::direct:
      check(KSPSetType(ksp_, KSPPREONLY), "KSPSetType");
      check(PCSetType(pc, PCLU), "PCSetType");
      check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "PCFactorSetMatSolverType");
      break;
    case LinearSolverKind::cg_amg:
    case LinearSolverKind::cg_gamg:
      check(KSPSetType(ksp_, KSPCG), "KSPSetType");
      break;
    case LinearSolverKind::gmres_amg:
    case LinearSolverKind::gmres_gamg:
      check(KSPSetType(ksp_, KSPGMRES), "KSPSetType");
      check(KSPGMRESSetRestart(ksp_, 100), "KSPGMRESSetRestart");
      check(KSPSetPCSide(ksp_, PC_RIGHT), "KSPSetPCSide");
      break;
  }
  if (uses_gamg(kind_)) {
    check(PCSetType(pc, PCGAMG), "PCSetType");
  } else if (kind_ != LinearSolverKind::direct) {
    check(PCSetType(pc, PCHYPRE), "PCSetType");
    check(PCHYPRESetType(pc, "boomeramg"), "PCHYPRESetType");
  }
  if (kind_ != LinearSolverKind::direct) {
    // The stopping rule on the true residual, ||b - A x|| <= tol ||b||, for both methods.
    check(KSPSetNormType(ksp_, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
    check(KSPSetTolerances(ksp_, 1e-10, 0.0, PETSC_DEFAULT, max_iterations_), "KSPSetTolerances");
  }
  // PETSc options with the prefix fem_ (PETSC_OPTIONS="-fem_pc_hypre_boomeramg_strong_threshold
  // 0.5" or "-fem_mat_mumps_icntl_14 50", say) tune every solver without a rebuild.
  check(KSPSetOptionsPrefix(ksp_, "fem_"), "KSPSetOptionsPrefix");
  check(KSPSetFromOptions(ksp_), "KSPSetFromOptions");
}

bool PetscLinearSolver::attempt(Mat A, Vec b, Vec x, int& iterations, std::string& reason) {
  if (!ksp_) configure();
  check(KSPSetOperators(ksp_, A, A), "KSPSetOperators");
  check(VecSet(x, 0.0), "VecSet");
  // Errors inside the factorization (a singular pivot) are reported, not fatal.
  const PetscErrorCode code = KSPSolve(ksp_, b, x);
  PetscInt n = 0;
  KSPGetIterationNumber(ksp_, &n);
  iterations = static_cast<int>(n);
  KSPConvergedReason converged;
  KSPGetConvergedReason(ksp_, &converged);
  if (code == 0 && converged > 0) return true;
  reason = code != 0 ? "PETSc error " + std::to_string(code)
                     : std::string(KSPConvergedReasons[converged]);
  return false;
}

LinearSolveResult PetscLinearSolver::solve(Mat A, Vec b, Vec x, double relative_tolerance,
                                           Vec node_coordinates) {
  LinearSolveResult result;
  if (node_coordinates) set_rigid_motions(A, node_coordinates);
  for (;;) {
    std::string reason;
    result.used = kind_;
    if (!ksp_) configure();
    if (kind_ != LinearSolverKind::direct)
      check(KSPSetTolerances(ksp_, relative_tolerance, 0.0, PETSC_DEFAULT, max_iterations_),
            "KSPSetTolerances");
    if (attempt(A, b, x, result.iterations, reason)) return result;
    if (kind_ == LinearSolverKind::direct)
      throw std::runtime_error(result.note + "direct solve failed (" + reason + ")");
    const LinearSolverKind next = next_in_chain(kind_);
    result.note += std::string(to_string(kind_)) + " failed after " +
                   std::to_string(result.iterations) + " iterations (" + reason +
                   "), switched to " + to_string(next) + "; ";
    kind_ = next;
    reset();
  }
}

}  // namespace tightfit
