#include "contact/blended_quadric_field.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace tightfit {
namespace {

// A unit vector normal to n.
Vec3 any_normal_to(const Vec3& n) {
  const Vec3 axis = std::abs(n.x()) < 0.6 ? Vec3::UnitX() : Vec3::UnitY();
  return (axis - axis.dot(n) * n).normalized();
}

// One vertex's quadric and weight at x.
struct Term {
  int vertex;
  double w;
  Vec3 dw;  // grad w
  Mat3 hw;  // Hessian of w
  double d;
  Vec3 dd;  // grad d = n + K (x - p)
};

}  // namespace

void BlendedQuadricField::build(const std::vector<Vec3>& vertices_m,
                                const std::vector<Triangle>& triangles,
                                const std::vector<Vec3>& vertex_normals) {
  p_ = vertices_m;
  n_ = vertex_normals;
  const int n = static_cast<int>(p_.size());
  std::vector<std::vector<int>> around(n);
  std::vector<int> a_triangle(n, 0);
  for (std::size_t k = 0; k < triangles.size(); ++k)
    for (int v : triangles[k]) a_triangle[v] = static_cast<int>(k);
  for (const Triangle& t : triangles)
    for (int k = 0; k < 3; ++k) {
      around[t[k]].push_back(t[(k + 1) % 3]);
      around[t[k]].push_back(t[(k + 2) % 3]);
    }
  neighbour_start_.assign(1, 0);
  neighbours_.clear();
  support_m_.assign(n, 0.0);
  beyond_squared_m2_.assign(n, 0.0);
  curvature_.assign(n, Mat3::Zero());
  for (int i = 0; i < n; ++i) {
    std::vector<int>& ring = around[i];
    std::sort(ring.begin(), ring.end());
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    neighbours_.insert(neighbours_.end(), ring.begin(), ring.end());
    neighbour_start_.push_back(static_cast<int>(neighbours_.size()));
    // The osculating quadric through the neighbours: n . e = -(a^2 k11 + 2 a b k12 + b^2 k22)/2
    // with (a, b) the edge's tangential coordinates; least squares over the ring.
    const Vec3 t1 = any_normal_to(n_[i]), t2 = n_[i].cross(t1);
    Eigen::Matrix3d normal_matrix = Eigen::Matrix3d::Zero();
    Vec3 right = Vec3::Zero();
    double longest = 0.0;
    for (int j : ring) {
      const Vec3 e = p_[j] - p_[i];
      longest = std::max(longest, e.norm());
      const double a = e.dot(t1), b = e.dot(t2);
      const Vec3 row(a * a, 2 * a * b, b * b);
      normal_matrix += row * row.transpose();
      right += row * (-2.0 * e.dot(n_[i]));
    }
    support_m_[i] = support_over_longest_edge * longest;
    beyond_squared_m2_[i] = (1.0 + 1e-9) * 4.0 * support_m_[i] * support_m_[i];
    // A ring too thin to fix all three (collinear neighbours) keeps the least-norm part: the
    // small ridge only matters in a direction no neighbour measures.
    normal_matrix += 1e-12 * (normal_matrix.trace() + 1e-300) * Mat3::Identity();
    const Vec3 k = normal_matrix.ldlt().solve(right);
    curvature_[i] = k[0] * t1 * t1.transpose() +
                    k[1] * (t1 * t2.transpose() + t2 * t1.transpose()) + k[2] * t2 * t2.transpose();
  }
  shift_m_.assign(n, 0.0);
  std::vector<double> misfit(n, 0.0);
  for (int sweep = 0; sweep < interpolation_sweeps; ++sweep) {
    for (int j = 0; j < n; ++j)
      misfit[j] = evaluate(p_[j], triangles[a_triangle[j]], n_[j], Mat3::Zero()).phi_m;
    for (int j = 0; j < n; ++j) shift_m_[j] -= misfit[j];
  }
}

BlendedQuadricField::Value BlendedQuadricField::evaluate(const Vec3& x, const Triangle& seed,
                                                         const Vec3& m, const Mat3& dm_dx) const {
  // The vertices whose support holds x, walked from the seed over the edges. The visit marks
  // live per thread and are stamped per query, so no query clears them.
  thread_local std::vector<unsigned> mark;
  thread_local unsigned stamp = 0;
  if (mark.size() < p_.size()) mark.assign(p_.size(), 0u);
  if (++stamp == 0) {
    std::fill(mark.begin(), mark.end(), 0u);
    stamp = 1;
  }
  thread_local std::vector<int> queue_storage;
  thread_local std::vector<Term> terms_storage;
  // Plain locals for the walk, so that the loop does not reach the thread's storage anew on
  // every vertex.
  std::vector<int>& queue = queue_storage;
  std::vector<Term>& terms = terms_storage;
  unsigned* const marks = mark.data();
  const unsigned this_query = stamp;
  queue.clear();
  terms.clear();
  for (int v : seed)
    if (marks[v] != this_query) marks[v] = this_query, queue.push_back(v);
  for (std::size_t q = 0; q < queue.size(); ++q) {
    const int i = queue[q];
    const Vec3 delta = x - p_[i];
    const bool seed_vertex = q < 3;
    // Most vertices the walk meets lie well beyond twice their support: their squared distance
    // tells so without the root and the division (a margin of 1e-9 keeps the test below exact).
    if (!seed_vertex && delta.squaredNorm() > beyond_squared_m2_[i]) continue;
    const double s = support_m_[i], distance = delta.norm(), r = distance / s;
    if (r >= 2.0 && !seed_vertex) continue;
    // The facing factor: S((n_i . m + 1/2) / (1/2)), S the quintic smoothstep.
    const double a = 2.0 * (n_[i].dot(m) + 0.5);
    if (r < 1.0 && a > 0.0) {
      // psi(r) = (1-r)^4 (4r+1): psi' = -20 r (1-r)^3, so grad w = -20 (1-r)^3 delta / s^2 and
      // its Hessian -20/s^2 [(1-r)^3 I - 3 (1-r)^2 delta delta^T / (|delta| s)].
      const double u = 1.0 - r;
      Term t;
      t.vertex = i;
      t.w = u * u * u * u * (4 * r + 1);
      t.dw = -20.0 * u * u * u * delta / (s * s);
      t.hw = -20.0 / (s * s) * u * u * u * Mat3::Identity();
      if (distance > 0) t.hw += 60.0 / (s * s) * u * u * delta * delta.transpose() / (distance * s);
      if (a < 1.0) {
        // w <- w S(a): grad (w S) = S grad w + w S' grad a, grad a = 2 (dm/dx)^T n_i; its
        // Hessian S H w + S' (grad w grad a^T + grad a grad w^T) + w S'' grad a grad a^T, the
        // second derivative of m left out (it only acts where S is between 0 and 1, on vertices
        // turned 90 to 120 degrees away, far out in the blend).
        const double S = a * a * a * (10 - 15 * a + 6 * a * a);
        const double dS = 30 * a * a * (1 - a) * (1 - a), d2S = 60 * a * (1 - a) * (1 - 2 * a);
        const Vec3 da = 2.0 * dm_dx.transpose() * n_[i];
        t.hw = S * t.hw + dS * (t.dw * da.transpose() + da * t.dw.transpose()) +
               t.w * d2S * da * da.transpose();
        t.dw = S * t.dw + t.w * dS * da;
        t.w *= S;
      }
      const Vec3 curved = curvature_[i] * delta;
      t.d = n_[i].dot(delta) + 0.5 * delta.dot(curved) + shift_m_[i];
      t.dd = n_[i] + curved;
      terms.push_back(t);
    }
    for (int k = neighbour_start_[i]; k < neighbour_start_[i + 1]; ++k) {
      const int j = neighbours_[k];
      if (marks[j] != this_query) marks[j] = this_query, queue.push_back(j);
    }
  }
  Value v;
  double weighted = 0.0;
  for (const Term& t : terms) {
    v.weight_sum += t.w;
    v.weight_gradient_per_m += t.dw;
    weighted += t.w * t.d;
  }
  if (!(v.weight_sum > 0)) return v;
  const double W = v.weight_sum;
  v.phi_m = weighted / W;
  // grad phi = sum [w_i grad d_i + (d_i - phi) grad w_i] / W.
  for (const Term& t : terms) v.gradient += (t.w * t.dd + (t.d - v.phi_m) * t.dw) / W;
  // From W phi = S differentiated twice:
  // H phi = sum [(d_i - phi) H w_i + grad w_i (grad d_i - grad phi)^T
  //              + (grad d_i - grad phi) grad w_i^T + w_i K_i] / W.
  for (const Term& t : terms) {
    const Vec3 dd = t.dd - v.gradient;
    v.hessian_per_m += ((t.d - v.phi_m) * t.hw + t.dw * dd.transpose() + dd * t.dw.transpose() +
                        t.w * curvature_[t.vertex]) /
                       W;
  }
  return v;
}

}  // namespace tightfit
