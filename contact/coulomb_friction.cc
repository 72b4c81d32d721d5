#include "contact/coulomb_friction.h"

#include <stdexcept>

namespace tightfit {

TangentialOffset tangential_offset(const RigidBody& body, const Vec3& x, const SurfacePoint& at_x,
                                   const SurfaceLocation& anchor, const NearFaces* near) {
  const Vec3& n = at_x.outward_normal;
  const Mat3& dn_dx = at_x.normal_derivative_per_m;
  const Vec3 d = x - body.surface_point_near_m(anchor, near);
  TangentialOffset offset;
  offset.u = d - n.dot(d) * n;
  // du/dx = P - n d^T dn/dx - (n.d) dn/dx, from u = d - n (n.d) with dd/dx = I.
  offset.du_dx =
      Mat3::Identity() - n * n.transpose() - n * (d.transpose() * dn_dx) - n.dot(d) * dn_dx;
  return offset;
}

FrictionResponse sticking_friction(const TangentialOffset& offset, double k) {
  FrictionResponse r;
  r.force_N = -k * offset.u;
  r.stiffness_N_per_m = k * offset.du_dx;
  return r;
}

FrictionResponse slipping_friction_along(const Vec3& t, double mu, double normal_force_N,
                                         const Vec3& dN_dx) {
  FrictionResponse r;
  r.slipping = true;
  r.force_N = -mu * normal_force_N * t;
  r.stiffness_N_per_m = mu * t * dN_dx.transpose();
  return r;
}

FrictionResponse coulomb_friction(const RigidBody& body, const Vec3& x, const SurfacePoint& at_x,
                                  double normal_force_N, const Vec3& dN_dx,
                                  const SurfaceLocation& anchor, const CoulombFrictionLaw& law,
                                  NearFaces* near, bool place_anchor) {
  if (!(law.friction_coefficient >= 0))
    throw std::invalid_argument("Friction/Coefficient: must not be negative");
  if (!(law.tangential_penalty_N_per_m > 0))
    throw std::invalid_argument("Friction/Tangential penalty: must be positive (N/m)");
  if (normal_force_N <= 0.0) {
    FrictionResponse r;
    r.anchor = at_x.location;
    return r;
  }
  const double k = law.tangential_penalty_N_per_m, mu = law.friction_coefficient;
  const TangentialOffset offset = tangential_offset(body, x, at_x, anchor, near);
  const double slip = offset.u.norm(), limit = mu * normal_force_N;
  if (k * slip <= limit) {
    FrictionResponse r = sticking_friction(offset, k);
    r.anchor = anchor;
    return r;
  }
  // Return mapping: the trial force -k u lies outside the cone |f| <= mu N; its projection
  // onto the cone keeps the direction: f = -mu N s, s = u / |u|. With ds/dx = (I - s s^T)
  // du/dx / |u|, -df/dx = mu s (dN/dx)^T + mu N (I - s s^T) du/dx / |u|.
  const Vec3 s = offset.u / slip;
  FrictionResponse r = slipping_friction_along(s, mu, normal_force_N, dN_dx);
  r.stiffness_N_per_m += limit / slip * (Mat3::Identity() - s * s.transpose()) * offset.du_dx;
  // The anchor slides towards x until the spring holds exactly mu N: k |u_new| = mu N. It is
  // placed back from x's own closest point, in the tangent plane there: a point measured from
  // the old anchor (a + u - (mu N / k) s) lies off a curved surface by about |u|^2 kappa / 2,
  // and after a long slip (a morphing body drags its anchors centimetres) projecting it back
  // moved the anchor far more than mu N / k, so that the committed anchor no longer gave the
  // force of the accepted state.
  if (!place_anchor) {
    r.anchor = anchor;
    return r;
  }
  const Vec3 slid = at_x.closest_point_m - (limit / k) * s;
  r.anchor = (near ? body.query_near(slid, *near) : body.query(slid)).location;
  return r;
}

}  // namespace tightfit
