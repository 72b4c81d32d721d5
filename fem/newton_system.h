// The linear system of one Newton iteration, K dx = -R, with the constraints that shape it:
// seams, held groups and the rigid-motion pin (fem_constraints.h) fix the matrix's pattern.
#pragma once

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>

namespace tightfit {

struct NewtonSystem {
  dealii::AffineConstraints<double> constraints;     // on increments
  dealii::PETScWrappers::MPI::SparseMatrix tangent;  // dR/dx, N/m
  dealii::PETScWrappers::MPI::Vector rhs;            // -R, N
  dealii::PETScWrappers::MPI::Vector increment;      // dx, m
};

}  // namespace tightfit
