// A fabric described by its tensile tests (the paper's Table 2, Section 4.2): per direction a
// force-strain curve (force per unit rest width, N/m, against engineering strain l/l0 - 1),
// the Poisson coefficient against weft strain, and a shear stiffness. docs/model.md
// ("Tensile curves") derives the strain energy built from them:
//
//   W = Phi1(e1) + Psi2(e2 + g(e1)) + 2 G e12^2
//
// with e = U - I the Biot strain (U = sqrt(C), in the grain axes), Phi1' = T1 the weft curve,
// g(e1) = nu(e1) e1 the warp contraction of a free weft strip, and Psi2' the warp curve
// re-expressed in the variable s = e2 + g(e1) so that a free warp strip reads T2 at its knots.
// A free weft strip (dW/de2 = 0 gives s = 0) then carries exactly T1(e1) and narrows by
// g(e1); a single straight segment per curve with a constant nu gives the linear Biot law.
#pragma once

#include "core/monotone_cubic.h"

#include <string>
#include <vector>

namespace tightfit {

struct CurvePoint {
  double strain = 0.0;  // engineering strain (l - l0) / l0, -
  double value = 0.0;   // N/m for a tension curve, - for the Poisson coefficient
};

// Parses "strain:value, strain:value, ..." (e.g. "0:0, 0.35:24.5, 0.6:49"). Throws
// std::invalid_argument naming `entry` and the piece it could not read, with `form` saying what
// a piece should look like.
std::vector<CurvePoint> parse_curve_points(
    const std::string& text, const std::string& entry,
    const std::string& form = "strain:value (e.g. 0.35:24.5)");
std::string format_curve_points(const std::vector<CurvePoint>& points);

struct TensileCurveData {
  std::vector<CurvePoint> weft_tension;  // N/m against weft strain; must pass through (0, 0)
  std::vector<CurvePoint> warp_tension;  // N/m against warp strain; must pass through (0, 0)
  std::vector<CurvePoint> poisson;       // nu12 against weft strain; constant beyond the data
  double shear_stiffness_N_per_m = 30.0;
};

class TensileCurves {
 public:
  // Throws std::invalid_argument naming the curve at fault (not increasing, no origin, a
  // Poisson coefficient that would turn a strip inside out, a warp curve that cannot be
  // re-expressed).
  explicit TensileCurves(const TensileCurveData& data);

  // The weft curve T1(e1), N/m per unit rest width, and its integral Phi1.
  template <class S>
  S weft_tension(const S& e1) const {
    return weft_.value(e1);
  }
  // The warp contraction of a free weft strip, g(e1) = nu(e1) e1.
  template <class S>
  S lateral_contraction(const S& e1) const {
    return poisson_.value(e1) * e1;
  }
  double lateral_contraction_slope(double e1) const;

  template <class S>
  S energy(const S& e1, const S& e2, const S& e12) const {
    return weft_.integral_from_zero(e1) +
           warp_in_s_.integral_from_zero(e2 + lateral_contraction(e1)) +
           2.0 * shear_N_per_m_ * e12 * e12;
  }
  // The weft tension of a strip held at its warp length (e2 = 0), N/m: dW/de1 there.
  double held_weft_tension(double e1) const;
  // The largest tangent stiffness at the knots, N/m (the stop rules' tension scale).
  double stiffness_scale() const { return stiffness_scale_; }

  // The weft strain of a free warp strip under warp tension tau (N/m): T1(e1) + tau g'(e1) = 0.
  double weft_strain_of_warp_strip(double tau_N_per_m) const;

 private:
  MonotoneCubic weft_, poisson_, warp_in_s_;
  double shear_N_per_m_;
  double stiffness_scale_ = 0.0;
};

}  // namespace tightfit
