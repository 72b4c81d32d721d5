#include "massspring/bending_hinges.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace tightfit {

namespace {

// The dihedral angle and its gradient with respect to the four corners (Bridson, Marino and
// Fedkiw 2003, Section 4). With e = b - a and n1, n2 the (unnormalised) normals of (a, b, c)
// and (b, a, d): moving c along n1 by delta turns its triangle about e by delta / h1
// (h1 = |n1| / |e| its height), which lowers theta; the edge corners take the opposite share of
// that turn, split by where the foot of c's height falls on the edge (t_c = 0 at a, 1 at b).
// Likewise for d. The finite-difference test checks every component.
struct AngleGradient {
  double theta_rad = 0.0;
  Vec3 grad[4];  // a, b, c, d; 1/m
};

AngleGradient angle_and_gradient(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 e = b - a;
  const Vec3 n1 = e.cross(c - a);        // normal of (a, b, c), length 2 A1
  const Vec3 n2 = (a - b).cross(d - b);  // normal of (b, a, d), length 2 A2
  const double e_length = e.norm();
  const double n1_squared = n1.squaredNorm(), n2_squared = n2.squaredNorm();
  AngleGradient out;
  if (!(e_length > 0) || !(n1_squared > 0) || !(n2_squared > 0)) {
    for (Vec3& g : out.grad) g.setZero();
    return out;  // a degenerate hinge carries no bending force
  }
  // sin theta |n1||n2| = (n1 x n2) . e/|e|, cos theta |n1||n2| = n1 . n2.
  out.theta_rad = std::atan2(n1.cross(n2).dot(e) / e_length, n1.dot(n2));
  // d theta / dc = -|e| n1 / |n1|^2, d theta / dd = -|e| n2 / |n2|^2.
  const Vec3 g1 = (e_length / n1_squared) * n1;
  const Vec3 g2 = (e_length / n2_squared) * n2;
  const double inv_e2 = 1.0 / (e_length * e_length);
  const double t_c = (c - a).dot(e) * inv_e2;  // foot of c's height on the edge, 0 at a
  const double t_d = (d - a).dot(e) * inv_e2;
  out.grad[2] = -g1;
  out.grad[3] = -g2;
  out.grad[0] = (1.0 - t_c) * g1 + (1.0 - t_d) * g2;
  out.grad[1] = t_c * g1 + t_d * g2;
  return out;
}

}  // namespace

double BendingHinges::dihedral_angle_rad(const Vec3& a, const Vec3& b, const Vec3& c,
                                         const Vec3& d) {
  return angle_and_gradient(a, b, c, d).theta_rad;
}

BendingHinges::BendingHinges(const SimulationMesh& mesh, double rigidity_N_m) {
  if (!(rigidity_N_m > 0)) return;  // no bending: no hinges
  // Directed edge (a, b) -> triangle having it in its counter-clockwise order.
  std::map<std::pair<int, int>, int> directed;
  for (std::size_t k = 0; k < mesh.triangles.size(); ++k)
    for (int i = 0; i < 3; ++i)
      directed[{mesh.triangles[k][i], mesh.triangles[k][(i + 1) % 3]}] = static_cast<int>(k);
  const std::vector<double> area = rest_triangle_areas(mesh);
  auto third_corner = [&](int k, int a, int b) {
    for (int v : mesh.triangles[k])
      if (v != a && v != b) return v;
    return -1;
  };
  for (const auto& [edge, k1] : directed) {
    const auto [a, b] = edge;
    if (a > b) continue;  // each interior edge once, from the side with a < b
    const auto other = directed.find({b, a});
    // Without a consistently oriented neighbour the edge is a boundary (or the mesh folds
    // on itself there): no hinge.
    if (other == directed.end()) continue;
    const int k2 = other->second;
    // Rest length of the edge in triangle k1's grain axes.
    const auto& t1 = mesh.triangles[k1];
    const int ia = static_cast<int>(std::find(t1.begin(), t1.end(), a) - t1.begin());
    const int ib = static_cast<int>(std::find(t1.begin(), t1.end(), b) - t1.begin());
    const double rest_length_m = (mesh.rest_triangles[k1][ib] - mesh.rest_triangles[k1][ia]).norm();
    Hinge h;
    h.a = a;
    h.b = b;
    h.c = third_corner(k1, a, b);
    h.d = third_corner(k2, a, b);
    h.stiffness_N_m = 3.0 * rigidity_N_m * rest_length_m * rest_length_m / (area[k1] + area[k2]);
    hinges_.push_back(h);
  }
}

double BendingHinges::energy_J(const std::vector<Vec3>& x) const {
  double energy = 0.0;
  for (const Hinge& h : hinges_) {
    const double theta = dihedral_angle_rad(x[h.a], x[h.b], x[h.c], x[h.d]);
    energy += 0.5 * h.stiffness_N_m * theta * theta;
  }
  return energy;
}

void BendingHinges::add_forces(const std::vector<Vec3>& x, std::vector<Vec3>& force_N) const {
  for (const Hinge& h : hinges_) {
    const AngleGradient ag = angle_and_gradient(x[h.a], x[h.b], x[h.c], x[h.d]);
    // f = -dE/dx = -k theta dtheta/dx.
    const double scale = -h.stiffness_N_m * ag.theta_rad;
    force_N[h.a] += scale * ag.grad[0];
    force_N[h.b] += scale * ag.grad[1];
    force_N[h.c] += scale * ag.grad[2];
    force_N[h.d] += scale * ag.grad[3];
  }
}

void BendingHinges::add_stiffness_bounds(const std::vector<Vec3>& x,
                                         std::vector<double>& stiffness_N_per_m) const {
  // Near flat the Hessian is k grad(theta) grad(theta)^T: its row sums bound the stiffness.
  for (const Hinge& h : hinges_) {
    const AngleGradient ag = angle_and_gradient(x[h.a], x[h.b], x[h.c], x[h.d]);
    double sum = 0.0;
    for (const Vec3& g : ag.grad) sum += g.norm();
    const int v[4] = {h.a, h.b, h.c, h.d};
    for (int i = 0; i < 4; ++i)
      stiffness_N_per_m[v[i]] += h.stiffness_N_m * ag.grad[i].norm() * sum;
  }
}

void BendingHinges::add_stiffness(const std::vector<Vec3>& x, Triplets& triplets) const {
  for (const Hinge& h : hinges_) {
    const AngleGradient ag = angle_and_gradient(x[h.a], x[h.b], x[h.c], x[h.d]);
    const int v[4] = {h.a, h.b, h.c, h.d};
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        add_block(triplets, v[i], v[j], h.stiffness_N_m * ag.grad[i] * ag.grad[j].transpose());
  }
}

}  // namespace tightfit
