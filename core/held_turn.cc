#include "core/held_turn.h"

#include <stdexcept>

namespace tightfit {

HeldTurn::HeldTurn(const std::vector<VertexConstraint>& constraints, int n_vertices) {
  std::vector<char> held(n_vertices, 0);
  const VertexConstraint* first = nullptr;
  for (const VertexConstraint& c : constraints) {
    if (c.kind != VertexConstraint::Kind::held_along_direction) return;
    if (first && (c.direction.normalized() - first->direction.normalized()).norm() > 1e-12) return;
    if (!first) first = &c;
    for (int v : c.vertices)
      if (v >= 0 && v < n_vertices) held[v] = 1;
  }
  if (!first || first->direction.norm() == 0.0) return;
  for (char h : held)
    if (!h) return;
  active_ = true;
  axis_ = first->direction.normalized();
}

bool HeldTurn::centre_of_mass(const std::vector<Vec3>& x, const std::vector<double>& mass_kg,
                              Vec3& centre) {
  double mass = 0.0;
  Vec3 sum = Vec3::Zero();
  for (std::size_t i = 0; i < x.size(); ++i) {
    sum += mass_kg[i] * x[i];
    mass += mass_kg[i];
  }
  if (!(mass > 0)) return false;
  centre = sum / mass;
  return true;
}

double HeldTurn::turn_rate(const std::vector<Vec3>& x, const std::vector<double>& mass_kg,
                           const std::vector<Vec3>& field, bool weighted, Vec3& centre,
                           double& inertia) const {
  if (x.size() != mass_kg.size() || x.size() != field.size())
    throw std::invalid_argument("HeldTurn: positions, masses and field differ in size");
  if (!centre_of_mass(x, mass_kg, centre)) return 0.0;
  double moment = 0.0;
  inertia = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Vec3 t = axis_.cross(x[i] - centre);
    moment += (weighted ? mass_kg[i] : 1.0) * t.dot(field[i]);
    inertia += mass_kg[i] * t.squaredNorm();
  }
  return inertia > 0 ? moment / inertia : 0.0;
}

double HeldTurn::remove_from_forces(const std::vector<Vec3>& x, const std::vector<double>& mass_kg,
                                    std::vector<Vec3>& force) const {
  if (!active_) return 0.0;
  Vec3 centre;
  double inertia = 0.0;
  const double acceleration = turn_rate(x, mass_kg, force, false, centre, inertia);
  for (std::size_t i = 0; i < x.size(); ++i)
    force[i] -= mass_kg[i] * acceleration * axis_.cross(x[i] - centre);
  return acceleration * inertia;
}

void HeldTurn::remove_from_velocities(const std::vector<Vec3>& x,
                                      const std::vector<double>& mass_kg,
                                      std::vector<Vec3>& velocity) const {
  if (!active_) return;
  Vec3 centre;
  double inertia = 0.0;
  const double rate = turn_rate(x, mass_kg, velocity, true, centre, inertia);
  for (std::size_t i = 0; i < x.size(); ++i) velocity[i] -= rate * axis_.cross(x[i] - centre);
}

}  // namespace tightfit
