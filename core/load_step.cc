#include "core/load_step.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace tightfit {

void StopRule::validate(bool zero_tolerance_allowed) const {
  if (!(relative_tolerance >= 0 && relative_tolerance < 1) ||
      (!zero_tolerance_allowed && relative_tolerance == 0))
    throw std::invalid_argument(
        std::string("Solver/Relative tolerance must be in ") +
        (zero_tolerance_allowed ? "[0, 1)" : "(0, 1) for the mass-spring backend"));
  if (!(contact_load_tolerance >= 0 && contact_load_tolerance < 1))
    throw std::invalid_argument("Solver/Contact load tolerance must be in [0, 1)");
  if (!(gap_tolerance_m > 0))
    throw std::invalid_argument("Solver/Gap tolerance must be positive (m)");
}

double StopRule::threshold_N(double rule_N, double contact_force_sum_N, long n_in_contact) const {
  if (!(contact_load_tolerance > 0) || n_in_contact <= 0) return rule_N;
  const double load_rule_N = contact_load_tolerance * contact_force_sum_N / double(n_in_contact);
  return std::min(rule_N, std::max(contact_load_floor * rule_N, load_rule_N));
}

double StopRule::resolvable_gap_m(double mean_rest_edge_m, double rest_area_m2) const {
  // The residual e Y h^2 / L over the stiffness Y of a vertex the membrane alone holds.
  return relative_tolerance * mean_rest_edge_m * mean_rest_edge_m / std::sqrt(rest_area_m2);
}

void StopRule::raise_gap_tolerance_to_stop_rule(double mean_rest_edge_m, double rest_area_m2) {
  if (gap_tolerance_auto)
    gap_tolerance_m = std::max(gap_tolerance_m, resolvable_gap_m(mean_rest_edge_m, rest_area_m2));
}

double ResidualSize::read(StopNorm norm, double largest_N, double sum_squared, double count) {
  if (!std::isfinite(sum_squared)) return std::numeric_limits<double>::quiet_NaN();
  return norm == StopNorm::rms ? std::sqrt(sum_squared / count) : largest_N;
}

void AlphaSecant::record(double alpha, bool in_contact) {
  if (!in_contact) {
    n_ = 0;
    return;
  }
  newest_ = 1 - newest_;
  alpha_[newest_] = alpha;
  n_ = std::min(n_ + 1, 2);
}

double AlphaSecant::ratio(double alpha) const {
  if (n_ < 2) return 0.0;
  const double last = alpha_[newest_], before = alpha_[1 - newest_];
  const double ratio = (alpha - last) / (last - before);
  return std::isfinite(ratio) && ratio > 0.0 && ratio <= 4.0 ? ratio : 0.0;
}

void AlphaSecant::extrapolate_multipliers(double ratio, const std::vector<double>& last,
                                          const std::vector<double>& before,
                                          std::vector<double>& multiplier_N) {
  for (std::size_t i = 0; i < multiplier_N.size(); ++i)
    multiplier_N[i] = std::max(0.0, last[i] + ratio * (last[i] - before[i]));
}

bool MultiplierRounds::run(StepReport& report) const {
  report.rounds.clear();
  report.multiplier_updates = 0;
  auto settle_round = [&](bool update) {
    report.rounds.push_back(settle());
    MultiplierRound& round = report.rounds.back();
    round.penetration_m = read_gap(update, &round.n_in_contact);
    if (update) ++report.multiplier_updates;
    return round.penetration_m;
  };
  bool closed = true;
  if (max_updates == 0) {
    settle_round(false);
  } else {
    for (;;) {
      // Settle, update; once the update finds the gap closed, (settle on the final multipliers
      // and read the gap there without updating).
      bool closed_now = settle_round(true) <= gap_tolerance_m;
      if (closed_now && settle_after_last_update)
        closed_now = settle_round(false) <= gap_tolerance_m;
      if (closed_now) break;
      if (report.multiplier_updates >= max_updates) {
        closed = false;
        break;
      }
    }
  }
  report.largest_penetration_m = report.rounds.back().penetration_m;
  report.n_in_contact = report.rounds.back().n_in_contact;
  return closed;
}

}  // namespace tightfit
