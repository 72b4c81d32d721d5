// Central differences of a material law's stress, the numbers its analytic tangent is checked
// against (docs/model.md, the laws on the Biot strain).
#pragma once

#include "core/material.h"

namespace tightfit::testing {

// dS/dE along Voigt column j of the tangent, a unit dE in (E11, E22, 2 E12), so dC = 2 dE,
// by central differences of step h at C.
inline Mat2 stress_derivative_along(const MaterialLaw& law, const Mat2& C, int j, double h) {
  Mat2 dC = Mat2::Zero();
  if (j < 2)
    dC(j, j) = 2.0 * h;
  else
    dC(0, 1) = dC(1, 0) = h;
  return (law.stress(C + dC) - law.stress(C - dC)) / (2.0 * h);
}

}  // namespace tightfit::testing
