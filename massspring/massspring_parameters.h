// Settings of the mass-spring backend: the "Mass spring" subsection of a parameter file.
// Plain data here; declaring and parsing live in the .cc, the only file that sees deal.II.
#pragma once

#include "core/load_step.h"

#include <string>

namespace dealii {
class ParameterHandler;
}

namespace tightfit {

// How the first load step starts (the paper's Section 4.3).
enum class Placement {
  // From the positions given to set_positions: for a tube, the garment already sewn round
  // the body (bodies/tube_placement.h). Fast: no seam has to close.
  sewn_tube,
  // The paper's start (Section 4.3, Figure 5): the panels unsewn, laid flat on opposite sides
  // of a cylinder body, pulled together by seam springs until the seams close; then welded.
  flat_panels,
};

// How a load step reaches its stable state.
enum class Integrator {
  // The paper's: damped fourth-order Runge-Kutta frames until the stop rule holds.
  rk4,
  // A regularised Newton iteration on the static equilibrium (static_newton.h): the same
  // forces, stop rule and contact multiplier updates, far fewer and costlier iterations.
  implicit,
};

// The stiffness the implicit route factorises (docs/backends.md, "The implicit route on the
// tops").
enum class ImplicitTangent { automatic, projected, exact };

struct MassSpringParameters {
  // The road to each stable state; the equilibrium, within the stop rule, is the same.
  Integrator integrator = Integrator::rk4;
  // Implicit: guard against non-convergence, factorisations per load step.
  int maximum_newton_iterations = 500;
  // Implicit: solves more per Newton iteration on the contact set the last solve predicts
  // (static_newton.h, StaticNewton::ContactSet); 0 = the contact set at the iteration's start.
  int contact_set_predictions = 0;
  // Implicit: the tangent's compressed triangles and contact blocks replaced by their positive
  // parts (positive_part.h), so that K + M / tau^2 stays positive definite on a compressed,
  // friction-held garment (the tops); exact: the analytic tangent, whose curvature terms make
  // Newton faster where it is positive definite (the stocking: 1.4 s against 6.9 s of CPU);
  // automatic: projected with friction, exact without.
  ImplicitTangent implicit_tangent = ImplicitTangent::automatic;
  // Implicit on a mesh body without friction, above 0: each load step starts with RK4 frames
  // until the residual is below this times the stop rule's tolerance (the garment's travel
  // onto the body), the contact rounds stop early as RK4's do (Inexact contact rounds), and a
  // Newton settle whose largest residual has not fallen by 10% in 10 iterations is finished
  // by RK4 frames. 0 = Newton alone.
  double implicit_approach_factor = 1000.0;
  // RK4 time step, s; 0 chooses it from the stiffest vertex (membrane, bending and penalty
  // contact) at the start of every load step.
  double time_step_s = 0.0;
  // With the automatic time step, above 0: the step is chosen again from the current state every
  // this many frames of a load step (less the stall test's halvings), as the dressing does. A
  // start with one squashed edge (a state carried from a coarse mesh) then does not keep the
  // whole settle at that edge's step. 0: chosen once, at the start of each load step.
  int time_step_update_frames = 0;
  // Fraction of the RK4 stability limit (2 sqrt(2) / omega_max) the automatic step uses.
  double time_step_safety = 0.9;
  // Mass scaling of the RK4 settle, dimensionless, above 0: with the automatic time step, a
  // particle whose stiffness bound over mass exceeds this many times the median particle's moves
  // with the mass that brings it to that bound (its weight stays its own), so that the few
  // stiffest, lightest particles (the small triangles at a pattern's short edges) do not set the
  // whole garment's time step. The stable state does not depend on the masses; only the frames
  // to reach it do. 0: every particle moves with its own mass.
  double mass_scaling_ratio = 4.0;
  // Mass-proportional damping c (the acceleration gets -c v), 1/s; 0 chooses it from the
  // garment's slowest membrane wave (critical_damping_per_s, stable_time_step.h).
  double damping_per_s = 0.0;
  // Above 0 (needs a net force tolerance): each load step starts with this mass-proportional
  // damping instead, 1/s, while the garment slides over the body as a whole, and takes the
  // damping above once the slide has ended. A tight top whose weight friction does not hold
  // where it was dressed creeps down at a speed the damping sets (its net force, the weight
  // friction does not hold, over m c): the automatic c, critical for the garment's slowest
  // membrane wave, is hundreds of 1/s and the creep takes seconds of simulated time; at a
  // lower c it slides faster, but vertices chatter on the faceted body. The slide has ended
  // when the damping force on the garment's mean velocity, m_total c_slide |vbar|, has stayed
  // below half the net force limit for three slide damping times (3 / c_slide); the stop rule
  // is read only after that (a creep at c_slide shows a net force c / c_slide times smaller).
  // Neither damping enters the stable state. 0: off.
  double slide_damping_per_s = 0.0;
  // Above 0 (needs a net force tolerance): a load step that does not start sliding (slide
  // damping 0) and whose stall test fires while it creeps slides at this damping, 1/s, instead of
  // halving its time step: a creep is the residual's own norm below the stop rule, the net force
  // on the garment above its limit and held for at least half by the damping of the garment's
  // mean velocity (m_total c |vbar|: the garment moves as a whole at the speed the damping lets
  // it). The slide ends as above and the step settles at its damping again; once per load step.
  // A top whose weight friction does not hold where it was dressed then slides to where it is
  // held at the lower damping instead of creeping there at the automatic one (docs/dressing.md,
  // "The creep at the stop"); a step that meets its rule without a stall is left as it was.
  // 0: off.
  double creep_slide_damping_per_s = 0.0;
  // Damping ratio zeta of each vertex's contact spring along the body's normal, dimensionless
  // in [0, 1]: a vertex in contact (lambda > 0) gets -2 zeta sqrt(kA m) (v . d) d (kA its
  // penalty stiffness, m its mass, d the gradient of its gap, which on a faceted body is the
  // face's normal, not the interpolated one the force takes: massspring_backend.h says why),
  // zeta = 1 the critical damping of the
  // mode of the mass on that spring. Tangential motion is not damped by it, so neither is a
  // slide over the body; the force is left out of the residual the stop rule reads (as the
  // damping above is). 0: off.
  double contact_normal_damping_ratio = 0.0;
  // Damping ratio of each sticking vertex's friction spring across the body's normal,
  // dimensionless in [0, 1]: a vertex in contact whose friction sticks (its tangential offset
  // from its anchor within the Coulomb cone) gets -2 zeta sqrt(kt m) (v - (v . n) n), kt its
  // tangential penalty stiffness. That spring is as stiff as the contact spring and the mass
  // damping is a hundredth of its critical damping: a stuck vertex in a crease between two
  // body parts (an armpit, the crotch) rings on it for thousands of frames and holds the rms
  // residual above the stop rule (docs/cookbook-jumpsuit.md); on a compression top the stuck
  // vertices on the body's flat faces ring so and stall its settle (docs/cookbook-dressed-top.md).
  // A slipping vertex is not damped,
  // so neither is a slide; the force is left out of the residual. 0: off.
  double contact_stick_damping_ratio = 0.0;
  // Frames of the paper's quasi-static start (velocity reset to zero every frame) before the
  // damped RK4 integration takes over.
  int quasi_static_frames = 30;
  // The stop rule and the gap tolerance: the case file's Solver entries, shared with the FE
  // backend (core/load_step.h).
  StopRule stop;
  // Stop rule on the garment as a whole: above 0, a state is stable only when the net force on
  // the garment (the sum of the residuals: what the body, friction and gravity leave
  // unbalanced) is also below this times the garment's weight (its mass times standard
  // gravity). The rms rule alone accepts a garment still sliding over the body: a net force F
  // spread over n vertices adds only F / n to each. 0: off.
  double net_force_tolerance = 0.0;
  // Guard against non-convergence: a load step that has not met the stop rule after this
  // many frames fails with an error.
  int maximum_frames = 200000;
  // Stall test (residual_history.h): a window of this many frames whose smallest residual is
  // not below stall_fall times the smallest of the earlier windows has stalled; the time step
  // is halved, up to stall_halvings times in a settle (each contact round starts again at the
  // stable step), and a stall after that ends the step with an error.
  int stall_window_frames = 2000;
  double stall_fall = 0.9;
  int stall_halvings = 2;
  // Contact multiplier updates (Uzawa) per load step: after each stable state every vertex's
  // multiplier becomes its contact force and the garment settles again, until the largest
  // penetration is below stop.gap_tolerance_m. 0 = the plain penalty (vertices sit p / k inside).
  int contact_updates = 10;
  // Inexact contact rounds, dimensionless, >= 0: a settle that a multiplier update will follow
  // stops once its residual is below this times the largest change that update would make to
  // a vertex's multiplier at the current state (kA |g| in contact), or below the stop rule,
  // whichever is larger; the settle after the last update, whose state is the result, always
  // meets the stop rule. Settling far below the force the next update moves each vertex by
  // only spends frames (inexact Uzawa: the update's error is of the order of the residual, so
  // a fraction of the update keeps its contraction). On a body whose queries are costly (a mesh
  // body, RigidBody::costly_queries), without friction and with the largest-residual stop rule
  // only: an analytic body's rounds are cheap, and a dressed top's rms residual lies far below
  // the update's largest change (its rounds then stopped within frames and the gap did not
  // close). 0: every settle meets the stop rule.
  double inexact_round_fraction = 0.02;
  // Bending rigidity B of the fabric, N m (a knit: about 1e-6 to 1e-5 N m).
  double bending_rigidity_N_m = 1e-6;
  // Start of the first load step.
  Placement placement = Placement::sewn_tube;
  // Flat panels: distance from the cylinder's surface to each panel's plane, m.
  double placement_gap_m = 0.005;
  // Flat panels: each zero-rest-length seam spring's stiffness is this times the law's
  // stiffness scale (N/m), dimensionless. A seam vertex pair balances the hoop pull T h (T the
  // tension, h the vertex's length of seam) at a gap T h / k, so the default keeps that gap a
  // few percent of an edge up to 50% strain.
  double seam_stiffness_factor = 20.0;

  // Throws std::invalid_argument naming the entry when a value is out of range.
  void validate() const;

  // The settle on a rough mesh body: one touched on its flat faces (Contact surface = faceted;
  // docs/dressing.md), or on its smooth surface by a garment held by friction, whose vertices
  // stick and slip (a top worn under gravity; docs/performance-bodies.md): these defaults, and the
  // stop rule's (the rms at 3e-3, StopRule), replace the ones above for the entries a case leaves
  // at auto. A few vertices next to the flat faces chatter in a contact limit cycle: a damper on
  // each contact spring along the face's normal (zeta 0.5) ends it without holding back a slide;
  // the time step chosen again every 100 frames, as a dressed state starts with squashed edges that
  // relax; the net force on the garment below 5 % of its weight, as the rms alone accepts a garment
  // still sliding; a creep under that rule slides at 50 1/s (creep_slide_damping_per_s).
  static MassSpringParameters on_rough_mesh_body();

  static void declare_parameters(dealii::ParameterHandler& prm);
  // Reads the "Mass spring" subsection (not `stop`: the caller sets it from the Solver one);
  // the entries at auto take on_rough_mesh_body()'s values when `rough_mesh_body`, the ones above
  // otherwise.
  // `arranged_from_landmarks`: the garment is dressed from afar, arranged from the body's
  // landmarks round its limbs or torso (Placement/Kind = pattern arrangement or arrangement),
  // where the auto stick damping is on.
  void parse_parameters(dealii::ParameterHandler& prm, bool rough_mesh_body = false,
                        bool arranged_from_landmarks = false);
};

}  // namespace tightfit
