// MeshBody's smooth contact surface (MeshBodyOptions::ContactSurface::smooth): the gap, its
// gradient and Hessian from the blended quadric field, and the surface location carried along
// the interpolated normal field (docs/bodies.md "The smooth contact surface").
#include "bodies/mesh_body.h"

#include <Eigen/Dense>

#include <cmath>

namespace tightfit {
namespace {

// The field's total weight W decides where it holds: near the surface W >= 0.35 (a point of a
// triangle lies within 0.58 of its longest edge from a corner whose support is 1.5 times that
// edge: r <= 0.39, psi >= 0.35), and it fades to 0 about half an edge off the surface.
// Between these weights the gap blends into the faceted one with the quintic smoothstep
// S(u) = u^3 (10 - 15 u + 6 u^2), C2 in W; no vertex is in contact there (the contact force
// only acts within lambda / (k A0), micrometres, of the surface).
constexpr double faceted_below_weight = 0.05, smooth_above_weight = 0.25;

}  // namespace

bool MeshBody::smooth_query(const Vec3& x, SurfacePoint& s, bool closest_point,
                            const NearFaces* near, Mat3* gap_hessian) const {
  const bool covered = smooth_field(x, s, near, gap_hessian);
  const double gap = s.signed_distance_m - skin_offset_m_;
  // Newton's steps y <- y - (g(y) - t) n(y) onto the skin's level set g = t: the first is off
  // it by about gap^2 |n^T H n| / 2, the field not being a distance along its normal exactly,
  // so a point more than 1e-7 m off (not in contact: there |gap| is within the gap tolerance,
  // 1e-8 m) takes two more.
  Vec3 y = x - gap * s.outward_normal;
  for (int step = 0; closest_point && step < 2 && std::abs(gap) > 1e-7; ++step) {
    SurfacePoint at = faceted_near(y, near);
    smooth_field(y, at, near);
    y -= (at.signed_distance_m - skin_offset_m_) * at.outward_normal;
  }
  s.closest_point_m = y;
  return covered;
}

bool MeshBody::smooth_field(const Vec3& x, SurfacePoint& s, const NearFaces* near,
                            Mat3* gap_hessian) const {
  // The blend's vertices kept for x's neighbourhood, where x lies in it (query_parts keeps them
  // with the near faces).
  const std::vector<int>* candidates =
      near && near->shape == shape_id_ && (x - near->centre_m).norm() <= near->reach_m
          ? &near->blend_vertices
          : nullptr;
  // The faceted answer's normal and derivative are the interpolated field's at the flat foot.
  const BlendedQuadricField::Value f =
      field_.evaluate(x, s.outward_normal, s.normal_derivative_per_m, candidates);
  const double u =
      (f.weight_sum - faceted_below_weight) / (smooth_above_weight - faceted_below_weight);
  if (u <= 0.0) return false;
  const double m = f.gradient.norm();
  if (!(m > 1e-6)) return false;
  // The gap g = phi / |grad phi|, a distance near the surface whatever the blend's scale:
  // grad g = n - phi H n / m^2 exactly (n = grad phi / m, grad m = H n), and its Hessian
  // Hg = (H - n (H n)^T - (H n) n^T) / m up to terms of order phi, which vanish on the surface.
  const Vec3 n = f.gradient / m, Hn = f.hessian_per_m * n;
  const double g = f.phi_m / m;
  Vec3 gradient = n - f.phi_m * Hn / (m * m);
  // The contact force's normal is the field's own, n = grad phi / |grad phi|, whose derivative
  // (I - n n^T) H / m is exact with the field's exact Hessian: the contact's tangent
  // kA n (grad g)^T - lambda dn/dx is then the force's derivative at any gap. The unit grad g
  // differs from n by phi H n / m^2 (order g times the blend's curvature), and its derivative
  // needs the field's third derivatives: left out, they made the tangent miss the force's
  // derivative by up to 3e5 1/m per metre of gap over a coarse ankle (3 1/m at 10 um inside,
  // against curvatures of 30 1/m), and Newton converged linearly there.
  Vec3 normal = n;
  Mat3 normal_derivative = (Mat3::Identity() - n * n.transpose()) * f.hessian_per_m / m;
  double gap = g;
  const bool covered = u >= 1.0;
  if (covered && gap_hessian)
    *gap_hessian = (f.hessian_per_m - n * Hn.transpose() - Hn * n.transpose()) / m;
  if (!covered) {
    // Out of contact (half an edge off the surface): the faceted answer blends in, and the
    // normal turns from the field's n to the blended gradient's direction.
    const double S = u * u * u * (10 - 15 * u + 6 * u * u);
    const double dS_dW =
        30 * u * u * (1 - u) * (1 - u) / (smooth_above_weight - faceted_below_weight);
    const Mat3 hessian = (f.hessian_per_m - n * Hn.transpose() - Hn * n.transpose()) / m;
    gap = S * g + (1 - S) * s.signed_distance_m;
    gradient = S * gradient + (1 - S) * s.gap_gradient +
               (g - s.signed_distance_m) * dS_dW * f.weight_gradient_per_m;
    normal = (gradient + S * f.phi_m * Hn / (m * m)).normalized();
    const Mat3 blended = S * hessian + (1 - S) * s.normal_derivative_per_m;
    normal_derivative = 0.5 * (blended + blended.transpose());
  }
  s.signed_distance_m = gap;
  s.gap_gradient = gradient;
  s.outward_normal = normal;
  s.normal_derivative_per_m = normal_derivative;
  s.closest_point_m = x - gap * s.outward_normal;
  return covered && f.every_vertex_facing;
}

SurfaceLocation MeshBody::smooth_location(const Vec3& y, int face) const {
  const auto& v = surface_.vertices_m;
  SurfaceLocation location;
  Vec3 b(1.0 / 3, 1.0 / 3, 1.0 / 3);
  for (int hop = 0; hop < 16; ++hop) {
    const Triangle& tri = surface_.triangles[face];
    const Vec3 &p0 = v[tri[0]], &n0 = vertex_normals_[tri[0]];
    const Vec3 e1 = v[tri[1]] - p0, e2 = v[tri[2]] - p0;
    const Vec3 m1 = vertex_normals_[tri[1]] - n0, m2 = vertex_normals_[tri[2]] - n0;
    // Newton on F(b1, b2, t) = p0 + b1 e1 + b2 e2 + t (n0 + b1 m1 + b2 m2) - y, from the flat
    // projection (t small: nearly linear, two or three steps).
    const Vec3 face_normal = e1.cross(e2).normalized();
    double t = (y - p0).dot(face_normal);
    Eigen::Matrix2d A;
    A << e1.dot(e1), e1.dot(e2), e1.dot(e2), e2.dot(e2);
    const Eigen::Vector2d in_plane =
        A.ldlt().solve(Eigen::Vector2d((y - p0).dot(e1), (y - p0).dot(e2)));
    double b1 = in_plane[0], b2 = in_plane[1];
    for (int iteration = 0; iteration < 8; ++iteration) {
      const Vec3 N = n0 + b1 * m1 + b2 * m2;
      const Vec3 F = p0 + b1 * e1 + b2 * e2 + t * N - y;
      Mat3 J;
      J.col(0) = e1 + t * m1;
      J.col(1) = e2 + t * m2;
      J.col(2) = N;
      const Vec3 step = J.partialPivLu().solve(F);
      b1 -= step[0], b2 -= step[1], t -= step[2];
      if (step.head<2>().cwiseAbs().maxCoeff() < 1e-14) break;
    }
    b = Vec3(1 - b1 - b2, b1, b2);
    int most_negative = 0;
    b.minCoeff(&most_negative);
    // Outside this triangle: on to the one across the edge opposite the most negative corner
    // (neighbours_[face][k] lies across the edge from corner k to corner k + 1).
    const int across = neighbours_[face][(most_negative + 1) % 3];
    if (b[most_negative] >= -1e-12 || across < 0) break;
    face = across;
  }
  b = b.cwiseMax(0.0);
  location.face = face;
  location.coordinates = b / b.sum();
  return location;
}

}  // namespace tightfit
