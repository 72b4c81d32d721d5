// The membrane's contribution at one quadrature point, with no finite-element library in
// sight: the deal.II assembly and the tests call the same arithmetic.
#pragma once

#include "core/material.h"
#include "core/types.h"

#include <Eigen/Core>

#include <vector>

namespace tightfit {

// Energy gradient and Hessian of W(C) dA at one point, for the node-major unknowns
// (x_0, y_0, z_0, x_1, ...) of the element's position field.
//   grad_N_grain: gradient of each node's shape function in the panel's grain axes, 1/m.
//   F: deformation gradient at the point, 3x2 (F = sum_a x_a grad_N_a^T).
//   JxW_m2: reference area the point stands for, m^2.
// energy_gradient_N (size 3n) gets dPi/dx_a = JxW F S grad_N_a (the internal force is minus
// it); tangent_N_per_m (3n x 3n, may be null) gets B_a^T D B_b + (grad_N_a . S grad_N_b) I.
void add_membrane_point(const MaterialLaw& law, const std::vector<Vec2>& grad_N_grain,
                        const Mat32& F, double JxW_m2, Eigen::VectorXd& energy_gradient_N,
                        Eigen::MatrixXd* tangent_N_per_m);

}  // namespace tightfit
