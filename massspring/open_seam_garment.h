// The garment with its seams still open, as particles: every panel vertex its own particle
// (unwelded_panels.h), the membrane and bending elements of the welded mesh, zero-rest-length
// seam springs between the copies of each welded vertex, penalty contact with a body and the
// held directions of the constraints. Integrated by damped RK4 frames; the two starts that sew
// a garment before its load steps (the paper's flat panels round a cylinder, FlatPanelStart;
// the dressing of a body, Dressing) drive it.
#pragma once

#include "bodies/rigid_body.h"
#include "core/backend.h"
#include "core/constrained_directions.h"
#include "core/worker_pool.h"
#include "massspring/bending_hinges.h"
#include "massspring/damped_rk4.h"
#include "massspring/massspring_parameters.h"
#include "massspring/seam_springs.h"
#include "massspring/triangle_elements.h"
#include "massspring/unwelded_panels.h"

#include <limits>
#include <memory>
#include <vector>

namespace tightfit {

class OpenSeamGarment {
 public:
  // `problem` (and what it points to) must outlive this object; its body is the contact body
  // unless set_body gives another. Seam springs of stiffness Mass spring/Seam stiffness factor
  // times the law's stiffness scale (N/m). Throws std::invalid_argument for an incomplete problem.
  OpenSeamGarment(const Problem& problem, const MassSpringParameters& parameters);

  // The body the particles touch (it must outlive this object; null: none).
  void set_body(const RigidBody* body);
  // The body has moved (grown) since the last call by at most `bound_m` anywhere, m: the
  // clearances kept to skip far particles' queries shrink by that much.
  void body_moved(double bound_m);
  // A particle found g outside the body stays outside while it moves less than this times g
  // (1 for a true distance; a body scaled about an axis by s, whose distance is carried over
  // from the unscaled one, needs s: bodies/scaled_body.h).
  void set_clearance_factor(double factor) { clearance_factor_ = factor; }
  // Scales every seam spring's stiffness: `fraction` of the full one (a ramp), dimensionless.
  void set_seam_fraction(double fraction);
  // No seam spring not yet sewn pulls harder than this, N (SeamSprings::set_pull_limit;
  // infinite: linear); a sewn one is `sewn_factor` times stiffer than the others.
  void set_seam_pull_limit(double pull_limit_N, double sewn_factor = 1.0);
  // Every seam pair closer than `closed_m` now is sewn for good (SeamSprings::sew_closed_pairs):
  // its spring no longer limited. Returns how many pairs are sewn.
  int sew_closed_seams(double closed_m) { return seams_.sew_closed_pairs(x_, closed_m); }
  // The full seam springs' stiffness, N/m.
  double full_seam_stiffness_N_per_m() const { return full_seam_stiffness_N_per_m_; }
  // Mass scaling for a motion that need not be true in time (the dressing): a particle whose
  // stiffness bound over mass exceeds `ratio` times the median particle's at the current
  // positions gets the mass that brings it to that bound, so that the few stiffest, lightest
  // particles (the small triangles at short seam edges) do not set the whole garment's time
  // step. Returns how many particles were made heavier. The equilibrium is unchanged (the
  // masses enter only the motion).
  int limit_stiffness_over_mass(double ratio);

  // Membrane + bending + seam + contact (+ gravity) force at `x` into `force`, held components
  // removed, N.
  void forces(const std::vector<Vec3>& x, bool gravity_on, std::vector<Vec3>& force) const;
  // One classical RK4 frame of x' = v, v' = f(x)/m - c v from positions() and velocities().
  void rk4_frame(double dt_s, double damping_per_s, bool gravity_on);
  // The stable RK4 time step at the current positions with the full seam stiffness (Mass
  // spring/Time step if given), s.
  double time_step_s() const;
  // Each particle's stiffness bound at the current positions (Gershgorin row sums), N/m.
  std::vector<double> stiffness_bounds_N_per_m() const;
  // Mass spring/Damping, or the critical damping of the garment's slowest membrane wave, 1/s.
  double damping_per_s() const;
  double largest_seam_gap_m() const { return seams_.largest_gap_m(x_); }
  // The seam vertex pair (unwelded indices) with the largest gap at the current positions.
  std::pair<int, int> widest_seam_pair() const;

  const UnweldedPanels& panels() const { return panels_; }
  const MassSpringParameters& parameters() const { return parameters_; }
  std::vector<Vec3>& positions() { return x_; }
  const std::vector<Vec3>& positions() const { return x_; }
  std::vector<Vec3>& velocities() { return v_; }
  double mean_edge_m() const { return mean_edge_m_; }
  double size_m() const { return size_m_; }

 private:
  Problem problem_;
  const RigidBody* body_ = nullptr;
  MassSpringParameters parameters_;
  UnweldedPanels panels_;
  TriangleElements elements_;
  BendingHinges hinges_;
  double full_seam_stiffness_N_per_m_ = 0.0;
  double seam_pull_limit_N_ = std::numeric_limits<double>::infinity();
  double sewn_factor_ = 1.0;
  SeamSprings seams_;
  std::vector<double> mass_kg_;
  std::vector<double> rest_vertex_area_m2_;
  ConstrainedDirections constrained_;
  double mean_edge_m_ = 0.0;
  double size_m_ = 0.0;

  std::vector<Vec3> x_, v_;
  DampedRk4 integrator_;
  // A particle whose last query found it g outside the body is outside, and feels no penalty
  // force, while it stays closer than g (less the body's motion since) to where it was asked:
  // the signed distance changes no faster than the point moves. Its next queries are skipped,
  // which spares the costly searches of a mesh body far from the garment.
  mutable std::vector<Vec3> asked_at_m_;
  mutable std::vector<double> clearance_m_;
  // The body's near faces of each particle (RigidBody::query_near).
  mutable std::vector<NearFaces> near_;
  double clearance_factor_ = 1.0;
  // Each particle's contact force at the last forces() and whether it was asked: the queries
  // are shared out to Problem::threads threads on a costly body, each particle writing only its
  // own entries here and above, and summed in particle order (the same forces with any number
  // of threads). The pool is made with the first costly body (contact/body_query_pool.h).
  mutable std::vector<Vec3> contact_N_;
  mutable std::vector<char> asked_;
  std::unique_ptr<WorkerPool> pool_;
};

}  // namespace tightfit
