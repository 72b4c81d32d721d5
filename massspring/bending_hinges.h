// Angular bending springs on the interior edges (the paper's Section 2.1).
//
// Each interior edge e shared by two triangles is a hinge with the dihedral angle theta
// (zero when the two triangles are coplanar: the panels are cut flat, so the rest angle is
// zero). Its energy is the "Discrete Shells" hinge energy (Grinspun, Hirani, Desbrun and
// Schroeder, SCA 2003, Eq. 3, with the stiffness of a plate of bending rigidity B):
//
//     E_e = (B / 2) * (3 |e0|^2 / (A1 + A2)) * theta^2,
//
// |e0| the edge's rest length and A1, A2 the two triangles' rest areas: (A1 + A2) / (3 |e0|)
// is the width of the strip the hinge stands for, so a sheet bent to a uniform curvature
// kappa stores B kappa^2 / 2 per unit area. The forces are minus the exact gradient of E_e,
// using the dihedral angle's gradient of Bridson, Marino and Fedkiw (SCA 2003, Section 4).
#pragma once

#include "core/garment.h"
#include "massspring/sparse_blocks.h"

#include <vector>

namespace tightfit {

class BendingHinges {
 public:
  // Finds the interior edges of `mesh` (edges shared by exactly two consistently oriented
  // triangles). `rigidity_N_m` is the fabric's bending rigidity B, N m.
  BendingHinges(const SimulationMesh& mesh, double rigidity_N_m);

  // Total bending energy, J.
  double energy_J(const std::vector<Vec3>& positions_m) const;
  // Adds the bending force on every vertex to force_N, N.
  void add_forces(const std::vector<Vec3>& positions_m, std::vector<Vec3>& force_N) const;
  // Adds an upper bound of each vertex's bending stiffness (N/m) in the current state.
  void add_stiffness_bounds(const std::vector<Vec3>& positions_m,
                            std::vector<double>& stiffness_N_per_m) const;

  // Appends the Gauss-Newton stiffness of every hinge, k grad(theta) grad(theta)^T (N/m), to
  // `triplets`: the Hessian of E_e without its k theta Hess(theta) term, which vanishes where
  // the wings are flat and stays small (theta of order h / radius) on a garment; it keeps the
  // matrix positive semi-definite for the Cholesky factorisation.
  void add_stiffness(const std::vector<Vec3>& positions_m, Triplets& triplets) const;

  std::size_t size() const { return hinges_.size(); }

  // The dihedral angle of one hinge, radians: edge a-b, c the third corner of the triangle
  // (a, b, c) and d of the triangle (b, a, d) (both counter-clockwise), in (-pi, pi]. Negative
  // when the wings fold towards the normal of (a, b, c) (a valley seen from that side).
  static double dihedral_angle_rad(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

 private:
  struct Hinge {
    int a, b, c, d;
    double stiffness_N_m;  // 3 B |e0|^2 / (A1 + A2)
  };
  std::vector<Hinge> hinges_;
};

}  // namespace tightfit
