// The paper's mass-spring backend (Section 2.1): particles with lumped mass, Volino's triangle
// elements, angular bending springs, penalty contact from contact/, integrated by
// fourth-order Runge-Kutta with mass-proportional damping after the paper's quasi-static
// start (velocity ignored). Time integration is only the road to the static equilibrium:
// a load step settles until the largest residual force is below a tolerance relative to the
// garment's tension scale, then (Contact multiplier updates) updates the contact multipliers
// and settles again until no vertex sits deeper in the body than the gap tolerance. With
// friction (Problem::friction_coefficient > 0) a load step is one quasi-static increment: its
// forces take the return mapping from the anchors of the last accepted state, and the stable
// state at the end of the step commits the new anchors (contact/friction_anchors.h).
//
// Placement (MassSpringParameters): "sewn tube" starts every load step from the positions
// given by set_positions. "flat panels" starts the first load step from the paper's flat
// panels instead (FlatPanelStart, Section 4.3): the positions set before it are ignored; once
// the seams have closed they are welded and that step continues on the sewn garment as usual.
// Positions set after the first step are used as with the sewn tube. That step's report counts
// the flat-panel frames in its iterations and its wall time, and reports them
// (StepReport::flat_start).
#pragma once

#include "contact/friction_anchors.h"
#include "core/backend.h"
#include "core/constrained_directions.h"
#include "core/held_turn.h"
#include "core/load_step.h"
#include "core/worker_pool.h"
#include "massspring/bending_hinges.h"
#include "massspring/damped_rk4.h"
#include "massspring/massspring_parameters.h"
#include "massspring/static_newton.h"
#include "massspring/triangle_elements.h"

#include <limits>
#include <memory>
#include <vector>

namespace tightfit {

class FlatPanelStart;

class MassSpringBackend final : public Backend {
 public:
  // `problem` (and everything it points to) must outlive the backend. Throws
  // std::invalid_argument when the problem is incomplete or a parameter is out of range.
  // With Placement = flat panels, also throws std::invalid_argument when the body is not a
  // Cylinder or the garment has fewer than two panels.
  MassSpringBackend(const Problem& problem, const MassSpringParameters& parameters);
  ~MassSpringBackend() override;

  std::string name() const override { return "massspring"; }
  void set_positions(const std::vector<Vec3>& positions_m) override;
  StepReport solve(const LoadStep& step) override;
  SurfaceState state() const override;

  // Particle masses, kg.
  const std::vector<double>& masses_kg() const { return mass_kg_; }
  // The stop rule's threshold, N.
  double tolerance_N() const { return tolerance_N_; }
  // The time step and damping of the last load step, s and 1/s.
  double time_step_s() const { return time_step_s_; }
  double damping_per_s() const { return damping_per_s_; }

  // Residual force on every particle (internal + contact + gravity when on, held components
  // removed) into `force`; returns the size the stop rule reads (Stop norm: the largest
  // magnitude or the root mean square), N (NaN when one is not finite). With a Net force
  // tolerance, the net force's share of it: max(norm, |sum f| x tolerance / net limit), so
  // one comparison with the tolerance asks both. `carried`: a later stage of an RK4 frame
  // (contact_force_N). The rule's threshold at x's contact load (StopRule::threshold_N) is kept
  // in stop_threshold_N_: the settles compare the size with it (settle_stop_N).
  double residual_forces(const std::vector<Vec3>& x, bool gravity_on, std::vector<Vec3>& force,
                         bool carried = false) const;
  // The net force on the garment (the sum of `force`), N, and the limit the stop rule puts on
  // its size (Net force tolerance times the garment's weight; 0 when off), N.
  static Vec3 net_force_N(const std::vector<Vec3>& force);
  double net_force_limit_N() const { return net_force_limit_N_; }
  // The residual's stiffness K = -d(residual)/dx at `x` (N/m, 3n x 3n, symmetric): the
  // triangles' exact stiffness, the hinges' Gauss-Newton one, each contact's and, at a held
  // vertex, the held directions projected out (and a unit diagonal put in their place).
  void stiffness(const std::vector<Vec3>& x, SparseMatrix& K) const;
  // The held turn's mode (held_turn.h) at `x`: w_i = m_i a x (x_i - c), 3n, the direction
  // the implicit route's increments are kept normal to (static_newton.h).
  void held_turn_mode(const std::vector<Vec3>& x, Eigen::VectorXd& w) const;

 private:
  // The implicit route's contact set: at the x stiffness() was last assembled at, each
  // vertex's body query, whether its contact is in the system, and the (held-projected)
  // diagonal block and force its contact put there.
  struct LinearisedContact {
    SurfacePoint surface;
    bool active = false;
    Mat3 block = Mat3::Zero();
    Vec3 force_N = Vec3::Zero();  // and the force it put into the right-hand side
  };
  mutable std::vector<LinearisedContact> linearised_contact_;
  // Vertex i's projection I - sum d d^T removing its held directions (identity when free).
  Mat3 held_projection(int i) const;
  // StaticNewton::ContactSet on the system stiffness() assembled last: each vertex whose
  // contact the increment `dx` opens or closes has its contact's force and stiffness taken
  // out of or put into `A` and `rhs`.
  bool predict_contact_set(const Eigen::VectorXd& dx, SparseMatrix& A, Eigen::VectorXd& rhs) const;
  // The held mode and the contact set prediction, where they apply.
  StaticNewton::Hooks newton_hooks() const;
  // Implicit on a mesh body without friction, with Implicit RK4 approach above 0: RK4 frames
  // take the garment onto the body and finish a Newton settle that stalls.
  bool rk4_assists_newton() const;
  // The implicit route factorises the projected tangent (massspring_parameters.h).
  bool projected_tangent() const;
  // A contact's 3x3 tangent block as the implicit route factorises it: with the projected
  // tangent its symmetric part's positive part (positive_part.h).
  Mat3 projected_block(const Mat3& block) const;

 private:
  // Internal (membrane + bending) force on every particle into `force`, N.
  void internal_forces(const std::vector<Vec3>& x, std::vector<Vec3>& force) const;
  // One RK4 frame of x' = v, v' = f(x)/m - c v from (x_, v_). Returns the residual force at
  // the frame's start (its first stage), N;
  // when `may_stop` and that is below the settle's stop there (settle_stop_N, kept in
  // frame_stop_N_), or not finite, the state is left untouched.
  double rk4_frame(double dt_s, double damping_per_s, bool gravity_on, bool may_stop);
  // Slide damping c_slide (1/s): `calm_s` (s) grows by dt while the damping force on the
  // garment's mean velocity, c_slide |sum m_i v_i|, is below half the net force limit, and
  // restarts at 0 otherwise; true once it reaches three slide damping times, 3 / c_slide.
  bool slide_has_ended(double dt_s, double c_slide, double& calm_s) const;
  // Creep slide damping: whether the last RK4 frame started in a creep (massspring_parameters.h:
  // the norm below its stop, the net force above its limit and held for at least half by the
  // damping `c` of the garment's mean velocity).
  bool creeping(double c) const;
  // The net force's limit against a threshold of the stop rule: the limit tightened in the ratio
  // the contact-load rule tightens the tension-scale one, N.
  double net_force_limit_at_N(double threshold_N) const;
  // The mass-weighted sum of the velocities, kg m/s.
  Vec3 momentum() const;
  // The automatic time step at the current state, with the mass scaling it allows
  // (MassSpringParameters::mass_scaling_ratio), which it keeps in inertia_kg_.
  double choose_time_step_s();
  // The largest depth of a vertex in contact at the current state, m; with
  // `update_multipliers`, Uzawa's update first: each vertex's multiplier becomes its contact
  // force (penalty_contact.h). `in_contact` (if given) counts the vertices in contact.
  double contact_penetration_m(bool update_multipliers, int* in_contact = nullptr);
  // The contact force on particle i at x: the normal force lambda n and, with friction, the
  // return mapping's tangential force from the step's anchors. `slipping` (if given) is set
  // when the vertex slips.
  // `carried`: a later stage of an RK4 frame, which may take the gap and normal carried over
  // from the frame's first stage (carried_contact_, below) instead of a query.
  Vec3 contact_force_N(std::size_t i, const Vec3& x, bool* slipping = nullptr,
                       bool carried = false) const;
  // contact_force_N of every particle at x into contact_N_, the particles shared out to the
  // pool's threads (Problem::threads) on a body whose queries are costly. Each particle's
  // evaluation reads and writes only its own entries of the per-particle state below (its near
  // faces, clearance, carried answer, damper directions, multiplier change, normal force,
  // friction anchor and the body's per-thread scratch), and the caller sums in particle order:
  // the same forces, to the last bit, with any number of threads.
  void contact_forces(const std::vector<Vec3>& x, bool carried) const;
  // Keeps the friction anchors of the accepted state x_; returns how many vertices slip there.
  int commit_friction_anchors();

  Problem problem_;
  MassSpringParameters parameters_;
  TriangleElements elements_;
  BendingHinges hinges_;
  std::vector<double> mass_kg_;
  // The masses RK4 moves the particles with: mass_kg_, the stiffest for their mass made heavier
  // by the mass scaling (choose_time_step_s). Weight, net force and momentum use mass_kg_.
  std::vector<double> inertia_kg_;
  std::vector<double> rest_vertex_area_m2_;
  ConstrainedDirections constrained_;
  HeldTurn held_turn_;  // every vertex held along one direction: the mean turn about it too
  double tolerance_N_ = 0.0;
  double net_force_limit_N_ = 0.0;  // 0: the stop rule does not read the net force
  double size_m_ = 0.0;             // the garment's rest size, sqrt(rest area)
  double time_step_s_ = 0.0;
  double damping_per_s_ = 0.0;

  // The paper's flat-panel start, waiting for the first load step (flat panels only).
  std::unique_ptr<FlatPanelStart> flat_start_;

  std::vector<Vec3> x_, v_;
  // Contact multiplier estimate of each particle, N (all zero: the plain penalty).
  std::vector<double> multiplier_N_;
  // Coulomb friction's anchors (inactive when Problem::friction_coefficient is 0).
  FrictionAnchors friction_;
  // The friction force on each particle at the accepted state, from the anchors the step began
  // with (the force the state is in equilibrium with); valid once the step has committed. The
  // committed anchors give it again only to within the projection of mu N / k_t onto the body.
  std::vector<Vec3> accepted_friction_N_;
  bool friction_committed_ = false;
  DampedRk4 integrator_;
  StaticNewton newton_;
  // Implicit integrator: the stable states (and multipliers) of the last two load steps in
  // contact, from which each step's start is extrapolated in alpha (core/load_step.h);
  // set_positions forgets them.
  AlphaHistory<std::vector<Vec3>> history_;
  // Moves x_ and multiplier_N_ to the secant's extrapolation at `alpha`.
  void predict(double alpha);
  // Keeps the state just settled at `alpha` for the secant (a step in contact).
  void record_settled(double alpha, bool in_contact);

  // The load step being solved: what its settles share (frames counted over the step, the
  // time step and its halvings, the slide) and what its report says.
  struct StepRun;
  std::unique_ptr<StepRun> run_;
  // The named stages of solve().
  void run_flat_start(const LoadStep& step, StepReport& report);
  void prepare_step(const LoadStep& step);
  MultiplierRound settle(const LoadStep& step);
  MultiplierRound settle_rk4(const LoadStep& step);
  MultiplierRound settle_implicit(const LoadStep& step);
  void finish_report(const LoadStep& step, StepReport& report);
  // A SolverError naming the step, frame and residual; `with_history` adds where the residual
  // sits and the stall test's windows.
  SolverError step_failure(StopReason reason, const std::string& what, bool with_history) const;

  // Force work space for the residual outside the frames, allocated once.
  mutable std::vector<Vec3> force_;
  // Each particle's contact force at the last residual, N (contact_forces).
  mutable std::vector<Vec3> contact_N_;
  // The threads the body queries are shared out to (contact/body_query_pool.h; null: this one).
  std::unique_ptr<WorkerPool> pool_;
  // Contact queries (contact_force_N), kept per particle between the frames of a step: the
  // body's near faces (RigidBody::query_near), and where the particle was last asked and its
  // signed distance there. The distance changes no faster than the point moves, so while a
  // particle stays within half that distance (less its multiplier's reach) of where it was
  // asked, it feels no contact force and its queries are skipped.
  mutable std::vector<NearFaces> near_;
  mutable std::vector<Vec3> asked_at_m_;
  mutable std::vector<double> clearance_m_;
  // The direction of each particle's contact damper (Contact normal damping ratio) at its last
  // evaluation, zero while out of contact, and each particle's damper coefficient
  // 2 zeta sqrt(kA m), N s/m (empty when off). The damper acts along the gap's gradient, not
  // along the force's normal: on the faceted body the force is kA (-g) n with n the
  // interpolated vertex normal, whose stiffness kA n (grad g)^T is not symmetric, and a damper
  // along n next to it lets some modes grow (the damped system's eigenvalues leave the left
  // half plane once n and grad g are 15 to 30 degrees apart, as Ziegler's damped column
  // does), while one along grad g damps the mode the spring kA acts on and leaves the rest.
  mutable std::vector<Vec3> damper_direction_;
  std::vector<double> contact_damper_N_s_per_m_;
  // The sticking vertices' friction dampers (Contact stick damping ratio), and the normal each
  // acts across, set by contact_force_N (zero: not sticking).
  std::vector<double> stick_damper_N_s_per_m_;
  mutable std::vector<Vec3> stick_normal_;
  // On a body whose queries are costly (RigidBody::costly_queries) and without friction, each
  // RK4 frame queries the body at its first stage only; the later stages take the gap and
  // normal to first order from that answer, g = g0 + grad g0 . (x - x0) and n = (n0 + dn/dx
  // (x - x0)) / |...|. The stop rule reads the first stage's residual, from the exact query,
  // so the stable state is the same; only the path to it changes, by the second-order terms of
  // a frame's displacement (micrometres against the body's centimetres of curvature radius).
  bool carry_contact_ = false;
  struct CarriedContact {
    bool valid = false;  // queried at this frame's first stage
    Vec3 x0_m, gap_gradient, normal;
    double gap_m = 0.0;
    Mat3 normal_derivative_per_m;
  };
  mutable std::vector<CarriedContact> carried_contact_;
  // Inexact contact rounds (MassSpringParameters::inexact_round_fraction): what Uzawa's update
  // would change each particle's multiplier by at its last evaluation, N, and the largest over
  // the particles at the last residual; and whether the next settle is the one after the last
  // update (which meets the stop rule itself).
  mutable std::vector<double> multiplier_change_N_;
  mutable double largest_multiplier_change_N_ = 0.0;
  // The normal contact force lambda on each particle at its last evaluation, N (0: not in
  // contact), and the stop rule's threshold at the contact load of the last residual
  // (StopRule::threshold_N), N.
  mutable std::vector<double> normal_force_N_;
  mutable double stop_threshold_N_ = 0.0;
  // The two parts of the stop rule's size at the last residual_forces, N: the residual's own
  // norm (Stop norm) and the net force's magnitude; and both at the start of the last RK4 frame.
  mutable double residual_norm_N_ = 0.0, residual_net_N_ = 0.0;
  // The threshold and the settle's stop there at the start of the last RK4 frame, N.
  double frame_norm_N_ = 0.0, frame_net_N_ = 0.0, frame_threshold_N_ = 0.0, frame_stop_N_ = 0.0;
  bool final_settle_next_ = true;
  // The residual below which the current settle stops at the state of the last residual_forces:
  // its threshold, or a round's inexact stop, or the implicit route's approach, N.
  double settle_stop_N() const;
  // True while the implicit route's approach runs RK4 frames (Implicit RK4 approach).
  bool approaching_ = false;
  // Adds each in-contact particle's damper -c (v . d) d to `force`, d = grad g.
  void add_contact_damping(const std::vector<Vec3>& v, std::vector<Vec3>& force) const;
};

}  // namespace tightfit
