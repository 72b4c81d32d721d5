// `Finite elements/Iterative solver memory` (petsc_linear_solver.h): 'lean' sets PETSc's
// all-at-once Galerkin product and a GMRES restart of 30, 'fast' takes back what 'lean' set,
// and an option the user gave is left as it is either way. (That both give the serial
// pressures is fem_mpi_two_ranks_cg_gamg_lean_match_serial's check.)
#include "fem/petsc_linear_solver.h"

#include <gtest/gtest.h>
#include <petscsys.h>

#include <string>

namespace tightfit {
namespace {

// PETSc (and MPI under it) for the whole test program.
struct PetscRuntime {
  PetscRuntime() { PetscInitializeNoArguments(); }
  ~PetscRuntime() { PetscFinalize(); }
};

// The option's value, "" when it is not set.
std::string option(const char* name) {
  char value[64] = "";
  PetscBool set = PETSC_FALSE;
  PetscOptionsGetString(nullptr, nullptr, name, value, sizeof(value), &set);
  return set ? value : "";
}

TEST(SolverMemory, LeanSetsTheOptionsAndFastTakesThemBack) {
  static PetscRuntime runtime;
  select_iterative_solver_memory(IterativeSolverMemory::lean);
  EXPECT_EQ(option("-matptap_via"), "allatonce");
  EXPECT_EQ(option("-fem_ksp_gmres_restart"), "30");
  select_iterative_solver_memory(IterativeSolverMemory::fast);
  EXPECT_EQ(option("-matptap_via"), "");
  EXPECT_EQ(option("-fem_ksp_gmres_restart"), "");

  // The user's restart stays through both; the product algorithm is still lean's to set.
  PetscOptionsSetValue(nullptr, "-fem_ksp_gmres_restart", "50");
  select_iterative_solver_memory(IterativeSolverMemory::lean);
  EXPECT_EQ(option("-fem_ksp_gmres_restart"), "50");
  EXPECT_EQ(option("-matptap_via"), "allatonce");
  select_iterative_solver_memory(IterativeSolverMemory::fast);
  EXPECT_EQ(option("-fem_ksp_gmres_restart"), "50");
  EXPECT_EQ(option("-matptap_via"), "");
  PetscOptionsClearValue(nullptr, "-fem_ksp_gmres_restart");
}

}  // namespace
}  // namespace tightfit
