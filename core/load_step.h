// What both backends do round a load step, written once: the stop rule and the size of the
// residual it reads, the secant predictor in alpha, and the contact multiplier (Uzawa) rounds
// (docs/backends.md, "Reaching equilibrium"; docs/model.md, "Contact"). Each backend brings its own
// physics and its own solver (RK4 frames or Newton's method) as the settle of one round.
#pragma once

#include "core/step_report.h"

#include <functional>
#include <string>
#include <vector>

namespace tightfit {

// The shared solver entries (the case file's Solver subsection, docs/parameters.md).
struct StopRule {
  // A state is stable when its residual (`norm`) is below this times the tension scale
  // Y h^2 / L (core/tension_scale.h). The FE backend alone may take 0: its own absolute rule,
  // 'Finite elements/Residual tolerance'.
  double relative_tolerance = 1e-4;
  StopNorm norm = StopNorm::largest;
  // Largest penetration of a vertex in contact at a finished step with multiplier updates, m.
  double gap_tolerance_m = 1e-8;
  // Solver/Gap tolerance = auto on a body mesh (Body/Kind = mesh or morph): gap_tolerance_m is
  // the default, raised to the gap the stop rule resolves on the garment's mesh
  // (raise_gap_tolerance_to_stop_rule).
  bool gap_tolerance_auto = false;
  // A rough mesh body: a mesh touched on its flat faces (Body/Mesh/Contact surface = faceted),
  // or on its smooth surface by a garment held by friction (Contact/Friction coefficient > 0):
  // the entries left at auto, here and in a backend's subsection, take their values for it
  // (the mass-spring settle's in massspring/massspring_parameters.h).
  bool rough_mesh_body = false;
  // The rule measured also against the step's own contact load: the residual must be below this
  // times the mean contact force on a vertex in contact as well (threshold_N); 0: off. Declared
  // last: FemParameters brace-initialises the fields above in order.
  double contact_load_tolerance = 1e-4;

  // The contact-load rule never asks for less than this fraction of the backend's rule: a
  // vertex that first touches carries a force near zero, and a settle asked for a residual near
  // zero would run for ever (docs/backends.md, "The stop rule at the contact load").
  static constexpr double contact_load_floor = 0.1;

  // The threshold a state's residual must be below, N: `rule_N`, the tension-scale rule's force
  // relative_tolerance Y h^2 / L (the FE backend then keeps its own absolute rule where that is
  // the tighter, fem/contact_rounds.cc), tightened to contact_load_tolerance times the mean contact
  // force on a vertex in contact, F = contact_force_sum_N / n_in_contact, but not below
  // contact_load_floor rule_N:
  //   threshold = min(rule_N, max(contact_load_floor rule_N, contact_load_tolerance F)).
  // A residual r on a vertex in contact is an error of up to r in its contact force, so the
  // mean pressure over the vertices in contact errs by at most r / F of itself (largest norm):
  // the pressure error is bounded relative to the pressure, not only the strain error. rule_N
  // alone without contact or with the rule off.
  double threshold_N(double rule_N, double contact_force_sum_N, long n_in_contact) const;

  // Throws std::invalid_argument naming the Solver entry when a value is out of range;
  // `zero_tolerance_allowed` for a backend with a rule of its own at 0.
  void validate(bool zero_tolerance_allowed) const;

  // The smallest penetration the stop rule can tell from zero on a mesh of mean rest edge h and
  // rest area L^2, m (docs/backends.md, "The gap the stop rule resolves"): a vertex at the border
  // of the contact area, its penalty spring off, is set by the membrane alone, a stiffness of
  // about the law's Y, and a settle leaves it a residual up to the stop rule's e Y h^2 / L, so
  // its place, and the penetration it brings into contact at the next update, is uncertain by
  // e h^2 / L, whatever Y. 0 when the relative rule is off (e = 0).
  double resolvable_gap_m(double mean_rest_edge_m, double rest_area_m2) const;
  // With gap_tolerance_auto, raises gap_tolerance_m to resolvable_gap_m: a gap the stop rule
  // cannot resolve is not asked for. A gap tolerance set in the case stays as set. (On the
  // analytic bodies the rounds close to 1e-8 m, each update dividing the gap by about 1 + k A / K,
  // and the light sheet on the plane needs them to, docs/backends.md.)
  void raise_gap_tolerance_to_stop_rule(double mean_rest_edge_m, double rest_area_m2);
};

// The size of a residual force field as the stop rule reads it: fed one size at a time (a
// vertex's force or a degree of freedom's component, N), then read over `count` of them (the
// vertices or nodes, for the rms). NaN when any was not finite.
class ResidualSize {
 public:
  void add(double size_N) {
    largest_N_ = size_N > largest_N_ ? size_N : largest_N_;
    sum_squared_ += size_N * size_N;  // a comparison drops NaN; the sum keeps it
  }
  // Largest size and sum of squares of this part (ranks combine them before reading).
  double largest_N() const { return largest_N_; }
  double sum_squared() const { return sum_squared_; }
  // The stop rule's size of the whole field from its parts' largest and sum of squares.
  static double read(StopNorm norm, double largest_N, double sum_squared, double count);
  double read(StopNorm norm, double count) const {
    return read(norm, largest_N_, sum_squared_, count);
  }

 private:
  double largest_N_ = 0.0;
  double sum_squared_ = 0.0;
};

// The secant (continuation) predictor in alpha through the last two converged steps in
// contact: a start, never the equilibrium. ratio() is how far past the last step the new alpha
// lies, in units of the last interval, or 0 (no prediction) with fewer than two such steps, a
// backward step, or one further than four intervals (there the secant misleads).
class AlphaSecant {
 public:
  void forget() { n_ = 0; }
  // A converged step at `alpha`; steps out of contact break the secant (the garment hangs
  // loose, and its positions say nothing of the next contact).
  void record(double alpha, bool in_contact);
  double ratio(double alpha) const;
  // 0 (newest) or 1: which of the two stored states a backend's own record is in.
  int newest() const { return newest_; }
  // The multipliers extrapolated by `ratio` from the last two steps' (kept non-negative).
  static void extrapolate_multipliers(double ratio, const std::vector<double>& last,
                                      const std::vector<double>& before,
                                      std::vector<double>& multiplier_N);

 private:
  int n_ = 0;
  int newest_ = 1;
  double alpha_[2] = {0.0, 0.0};
};

// The last two converged steps in contact, kept for the secant predictor: the backend's state
// (the mass-spring positions, the FE degrees of freedom) and the contact multipliers at each.
template <class State>
class AlphaHistory {
 public:
  // A garment placed anew: its history says nothing of where it goes next.
  void forget() { secant_.forget(); }
  // A converged step at `alpha`, its state and multipliers kept when in contact.
  void record(double alpha, bool in_contact, const State& state,
              const std::vector<double>& multiplier_N) {
    secant_.record(alpha, in_contact);
    if (!in_contact) return;
    state_[secant_.newest()] = state;
    multiplier_N_[secant_.newest()] = multiplier_N;
  }
  // The start at `alpha`: the multipliers extrapolated into `multiplier_N`, and
  // `extrapolate_state(ratio, last, before)` called to extrapolate the state the backend's way
  // (last + ratio (last - before)). Returns the ratio, 0 (nothing changed) when there is no
  // prediction.
  template <class ExtrapolateState>
  double predict(double alpha, std::vector<double>& multiplier_N,
                 ExtrapolateState&& extrapolate_state) const {
    const double ratio = secant_.ratio(alpha);
    if (ratio == 0.0) return 0.0;
    const int last = secant_.newest(), before = 1 - last;
    extrapolate_state(ratio, state_[last], state_[before]);
    AlphaSecant::extrapolate_multipliers(ratio, multiplier_N_[last], multiplier_N_[before],
                                         multiplier_N);
    return ratio;
  }

 private:
  AlphaSecant secant_;
  State state_[2];
  std::vector<double> multiplier_N_[2];
};

// One load step's contact multiplier (Uzawa) rounds: the backend's settle at fixed
// multipliers, then every vertex's multiplier becomes its contact force, until no vertex in
// contact is deeper than the gap tolerance. What happens after the update that closes the gap
// depends on what the backend reports as contact force: one that reports the multiplier itself
// (the FE backend) is done, since the state it solved is in equilibrium with the updated
// multipliers; one that reads its contact force from the state, max(0, lambda - kA g) (the
// mass-spring backend), settles once more on the final multipliers and reads the gap again
// there, without updating (the settle moves each vertex by up to its kA g).
struct MultiplierRounds {
  // Settles at the current multipliers; returns what the round did (penetration_m and
  // n_in_contact are filled by the rounds).
  std::function<MultiplierRound()> settle;
  // The largest penetration of a vertex in contact, m, and (when `count` is not null) how many
  // are in contact; with `update`, each multiplier first becomes the contact force.
  std::function<double(bool update, int* count)> read_gap;
  // Updates allowed; the rounds fail when the gap is still open after the last (0: the plain
  // penalty, one settle and no update).
  int max_updates = 0;
  double gap_tolerance_m = 1e-8;
  bool settle_after_last_update = true;

  // Runs the rounds into `report` (rounds, multiplier_updates, largest_penetration_m,
  // n_in_contact); returns false when the gap did not close within max_updates.
  bool run(StepReport& report) const;
};

}  // namespace tightfit
