// Volino's triangle element (Volino, Magnenat-Thalmann and Faure, "A simple approach to
// nonlinear tensile stiffness for accurate cloth simulation", ACM TOG 28(4), 2009; the
// paper's Section 2.1): the membrane law integrated over each linear triangle.
//
// A triangle of rest area A0 and constant deformation gradient F (3x2) stores the energy
// A0 W(C), C = F^T F. With F = sum_i x_i g_i^T (g_i the rest-shape gradients of the linear
// shape functions) the force on corner i is f_i = -dE/dx_i = -A0 P g_i, P = F S, S = 2 dW/dC:
// exactly minus the gradient of the energy, so the element conserves momentum and a rigid
// motion gives no force.
#pragma once

#include "core/garment.h"
#include "core/material.h"
#include "massspring/sparse_blocks.h"

#include <vector>

namespace tightfit {

class TriangleElements {
 public:
  // Precomputes the rest-shape gradients and areas of every triangle of `mesh`. `law` must
  // outlive this object.
  TriangleElements(const SimulationMesh& mesh, const MaterialLaw& law);

  // Total membrane energy, J.
  double energy_J(const std::vector<Vec3>& positions_m) const;
  // Adds the membrane force on every vertex to force_N (sized to the vertex count), N.
  void add_forces(const std::vector<Vec3>& positions_m, std::vector<Vec3>& force_N) const;
  // Upper bound of the stiffness (N/m) each vertex sees from its triangles in the current
  // state, for the stable time step: a Gershgorin row sum of the element stiffness built from
  // the law's tangent and the geometric (stress) term. Added to stiffness_N_per_m.
  void add_stiffness_bounds(const std::vector<Vec3>& positions_m,
                            std::vector<double>& stiffness_N_per_m) const;

  // Appends the exact stiffness K = -df/dx (N/m) of every triangle, its nine 3x3 vertex blocks
  // K_ij = A0 [B_i^T D B_j + (g_i . S g_j) I] (D the law's tangent, S its stress, B_j the
  // strain's derivative by x_j in Voigt order: rows g_j1 F1^T, g_j2 F2^T, g_j2 F1^T + g_j1 F2^T
  // with F1, F2 the columns of F), to `triplets`. `projected`: a triangle whose stress S or
  // tangent D is not positive semi-definite (compressed) adds the positive part of its 9x9
  // stiffness instead (positive_part.h), as a tension-field membrane has no compressive
  // stiffness; the others add their exact one, positive semi-definite already.
  void add_stiffness(const std::vector<Vec3>& positions_m, Triplets& triplets,
                     bool projected = false) const;

  std::size_t size() const { return elements_.size(); }

 private:
  struct Element {
    std::array<int, 3> vertex;
    std::array<Vec2, 3> gradient;  // g_i = grad N_i in the grain axes, 1/m
    double rest_area_m2;
  };
  Mat32 deformation_gradient(const Element& e, const std::vector<Vec3>& x) const {
    return x[e.vertex[0]] * e.gradient[0].transpose() + x[e.vertex[1]] * e.gradient[1].transpose() +
           x[e.vertex[2]] * e.gradient[2].transpose();
  }

  const MaterialLaw& law_;
  std::vector<Element> elements_;
};

}  // namespace tightfit
