// The garment's mean turn about the held direction, held when every vertex is held along one
// direction (Constraints/Held groups = all: a stocking's knit gripped along the leg). Holding
// the axial coordinate blocks the slide along the axis and the turns about any line across
// it; the turn about the axis is the one rigid motion left, and a nearly round limb resists it
// only through being not quite round, so a frictionless tube creeps round the leg for tens of
// thousands of frames before it settles (docs/backends.md, "The held turn"). The grip that
// holds the knit along the leg holds its mean turn too.
//
// The constraint is on the mass-weighted mean turn: with t_i = a x (x_i - c), c the centre of
// mass and a the held direction, the angular momentum sum_i m_i t_i . v_i about the axis stays
// zero. Its reaction is the torque tau = sum_i t_i . f_i spread as the forces m_i t_i tau / I,
// I = sum_i m_i |t_i|^2: it leaves the net force unchanged (sum_i m_i t_i = 0) and, t_i being
// normal to a, the held coordinates too.
#pragma once

#include "core/backend.h"
#include "core/types.h"

#include <vector>

namespace tightfit {

class HeldTurn {
 public:
  HeldTurn() = default;
  // Active when the constraints hold every one of the mesh's `n_vertices` vertices along one
  // direction.
  HeldTurn(const std::vector<VertexConstraint>& constraints, int n_vertices);

  bool active() const { return active_; }
  const Vec3& axis() const { return axis_; }
  // Removes the turn's angular acceleration from `force` (N): afterwards sum_i t_i . f_i = 0.
  // Returns the torque removed, N m.
  double remove_from_forces(const std::vector<Vec3>& x, const std::vector<double>& mass_kg,
                            std::vector<Vec3>& force) const;
  // The vertices' centre of mass (m), the point the held axis passes through; false (and
  // `centre` unset) when their mass is not positive.
  static bool centre_of_mass(const std::vector<Vec3>& x, const std::vector<double>& mass_kg,
                             Vec3& centre);
  // Removes the turn from `velocity` (m/s): afterwards sum_i m_i t_i . v_i = 0.
  void remove_from_velocities(const std::vector<Vec3>& x, const std::vector<double>& mass_kg,
                              std::vector<Vec3>& velocity) const;

 private:
  // The angular velocity (or acceleration) of the best rigid turn in `field` about the axis
  // through the centre of mass `centre`; `weighted`: the field is per unit mass (velocities).
  // `inertia`: I = sum_i m_i |t_i|^2, kg m^2.
  double turn_rate(const std::vector<Vec3>& x, const std::vector<double>& mass_kg,
                   const std::vector<Vec3>& field, bool weighted, Vec3& centre,
                   double& inertia) const;

  bool active_ = false;
  Vec3 axis_ = Vec3::UnitZ();
};

}  // namespace tightfit
