// A body seen shrunk (or grown) by a factor s about a point or about an axis: the surface of
// `body` mapped by T(y) = c + P (y - c) + s (I - P) (y - c), with P = 0 about the point c, and
// P = a a^T about the axis through c along a (lengths along the axis kept). Inside and outside
// map exactly. The query maps x back, y = T^-1(x), asks the body and carries its answer over:
// closest point T(p), outward normal m = T^-T n / |T^-T n| with T^-T n = P n + (I - P) n / s,
// signed distance g / |T^-T n| (for y - p = g n, m . (x - T(p)) = g (T^-T n) . (T n) / |T^-T n|
// = g / |T^-T n|). About a point this is exact (s g, the same normal); about an axis it is exact
// along the axis and across it and a first-order estimate near the surface elsewhere, which is
// what a contact penalty needs while the body grows. The dressing of a body
// (massspring/dressing.h) starts it shrunk inside the open garment and grows it back to s = 1.
#pragma once

#include "bodies/shrinking_body.h"

namespace tightfit {

class ScaledBody final : public ShrinkingBody {
 public:
  // About the point `centre_m`; `body` must outlive this object. Scale 1 until set_scale.
  ScaledBody(const RigidBody& body, const Vec3& centre_m);
  // About the axis through `centre_m` along `axis` (not zero).
  ScaledBody(const RigidBody& body, const Vec3& centre_m, const Vec3& axis);

  // Throws std::invalid_argument unless the scale is positive.
  void set_scale(double scale) override;
  double scale() const override { return scale_; }
  // The farthest vertex of the body's display mesh from the centre (or the axis), m.
  double reach_m() const override { return reach_m_; }

  std::string name() const override { return body_.name() + " (scaled)"; }
  SurfacePoint query(const Vec3& x) const override;
  // The body's own query_near at the point mapped back: `near` is kept in the body's own frame.
  SurfacePoint query_near(const Vec3& x, NearFaces& near) const override;
  SurfacePoint query_parts(const Vec3& x, NearFaces& near, QueryParts parts) const override;
  bool costly_queries() const override { return body_.costly_queries(); }
  DisplayMesh display_mesh() const override;
  Vec3 surface_point_m(const SurfaceLocation& location) const override;

 private:
  Vec3 scaled(const Vec3& y) const;    // T(y)
  Vec3 unscaled(const Vec3& x) const;  // T^-1(x)
  // The body's answer at T^-1(x) carried over to x.
  SurfacePoint carried(SurfacePoint s) const;

  const RigidBody& body_;
  Vec3 centre_m_;
  Mat3 along_ = Mat3::Zero();  // P
  double scale_ = 1.0;
  double reach_m_ = 0.0;
  void find_reach();
};

}  // namespace tightfit
