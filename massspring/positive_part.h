// The positive semi-definite part of a symmetric stiffness block: its eigenvalues below zero
// set to zero, its eigenvectors kept (the nearest positive semi-definite matrix in the
// Frobenius norm, Higham, Linear Algebra Appl. 103, 1988). The implicit route's projected
// tangent (static_newton.h) takes it per element: a compressed triangle's, a contact's with
// its curvature and friction terms; in tension they are positive semi-definite already and
// stay exact (docs/backends.md, "The implicit route on the tops").
#pragma once

#include "core/types.h"

#include <Eigen/Core>

namespace tightfit {

using Mat9 = Eigen::Matrix<double, 9, 9>;

// The positive part of the symmetric part (A + A^T) / 2 of a 3x3 block.
Mat3 positive_part(const Mat3& block);
// In place, for a symmetric 9x9 block (a triangle's three vertices).
void clamp_to_positive_part(Mat9& block);

}  // namespace tightfit
