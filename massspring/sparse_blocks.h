// Sparse matrices of 3x3 vertex blocks, the stiffness K = -df/dx of the implicit settle
// (static_newton.h): row and column 3 v + k is component k of vertex v.
#pragma once

#include "core/types.h"

#include <Eigen/SparseCore>

#include <vector>

namespace tightfit {

using SparseMatrix = Eigen::SparseMatrix<double>;
using Triplets = std::vector<Eigen::Triplet<double>>;

// Appends block (i, j) (every entry, zeros too, so the pattern does not depend on the state).
inline void add_block(Triplets& triplets, int i, int j, const Mat3& block) {
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) triplets.emplace_back(3 * i + r, 3 * j + c, block(r, c));
}

}  // namespace tightfit
