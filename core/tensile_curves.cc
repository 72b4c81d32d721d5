#include "core/tensile_curves.h"
#include "core/number_text.h"
#include "core/plain_text.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace tightfit {

namespace {

double parse_number(const std::string& text, const std::string& entry, const std::string& piece,
                    const std::string& form) {
  const std::optional<double> value = whole_number(text);
  if (!value) throw std::invalid_argument(entry + ": cannot read '" + piece + "' as " + form);
  return *value;
}

std::vector<double> strains(const std::vector<CurvePoint>& points) {
  std::vector<double> x;
  for (const CurvePoint& p : points) x.push_back(p.strain);
  return x;
}
std::vector<double> values(const std::vector<CurvePoint>& points) {
  std::vector<double> y;
  for (const CurvePoint& p : points) y.push_back(p.value);
  return y;
}

// A tension curve: strictly increasing strains and forces, through the origin.
MonotoneCubic tension_curve(const std::vector<CurvePoint>& points, const std::string& name) {
  if (points.size() < 2)
    throw std::invalid_argument(name + " needs at least two points, (0, 0) among them");
  bool origin = false;
  for (std::size_t k = 0; k < points.size(); ++k) {
    origin = origin || (points[k].strain == 0.0 && points[k].value == 0.0);
    if (k > 0 &&
        !(points[k].strain > points[k - 1].strain && points[k].value > points[k - 1].value))
      throw std::invalid_argument(name +
                                  ": strain and force must both increase from point to point");
  }
  if (!origin) throw std::invalid_argument(name + " must pass through 0:0 (no force at rest)");
  return MonotoneCubic(strains(points), values(points), MonotoneCubic::Ends::linear);
}

MonotoneCubic poisson_curve(const std::vector<CurvePoint>& points, const std::string& name) {
  if (points.empty()) throw std::invalid_argument(name + " needs at least one point");
  for (const CurvePoint& p : points)
    if (!(p.value >= 0.0 && p.value < 1.0))
      throw std::invalid_argument(name + ": every coefficient must lie in [0, 1)");
  try {
    return MonotoneCubic(strains(points), values(points), MonotoneCubic::Ends::flat);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(name + ": " + e.what());
  }
}

}  // namespace

std::vector<CurvePoint> parse_curve_points(const std::string& text, const std::string& entry,
                                           const std::string& form) {
  std::vector<CurvePoint> points;
  std::stringstream list(text);
  for (std::string piece; std::getline(list, piece, ',');) {
    piece = trimmed(piece);
    if (piece.empty()) continue;
    const auto colon = piece.find(':');
    if (colon == std::string::npos)
      throw std::invalid_argument(entry + ": cannot read '" + piece + "' as " + form);
    points.push_back({parse_number(trimmed(piece.substr(0, colon)), entry, piece, form),
                      parse_number(trimmed(piece.substr(colon + 1)), entry, piece, form)});
  }
  return points;
}

std::string format_curve_points(const std::vector<CurvePoint>& points) {
  std::ostringstream out;
  for (std::size_t k = 0; k < points.size(); ++k)
    out << (k ? ", " : "") << points[k].strain << ":" << points[k].value;
  return out.str();
}

namespace {

// The warp curve re-expressed in s = e2 + g(e1): at each knot (e2, tau) a free warp strip has
// the weft strain e1(tau) and so s = e2 + g(e1(tau)); Psi2' interpolates (s, tau).
MonotoneCubic warp_in_s(const TensileCurves& curves, const std::vector<CurvePoint>& warp) {
  tension_curve(warp, "Material/Tension curve warp");  // checks the points
  std::vector<double> s, tau;
  for (const CurvePoint& p : warp) {
    s.push_back(p.strain + curves.lateral_contraction(curves.weft_strain_of_warp_strip(p.value)));
    tau.push_back(p.value);
    if (s.size() > 1 && !(s.back() > s[s.size() - 2]))
      throw std::invalid_argument(
          "Material/Tension curve warp: with the Poisson curve the warp strip's strains do not "
          "increase; the Poisson coefficient changes too fast");
  }
  return MonotoneCubic(s, tau, MonotoneCubic::Ends::linear);
}

}  // namespace

TensileCurves::TensileCurves(const TensileCurveData& data)
    : weft_(tension_curve(data.weft_tension, "Material/Tension curve weft")),
      poisson_(poisson_curve(data.poisson, "Material/Poisson curve")),
      // The constant placeholder is replaced below, once weft and Poisson curves exist.
      warp_in_s_({0.0}, {0.0}, MonotoneCubic::Ends::flat),
      shear_N_per_m_(data.shear_stiffness_N_per_m) {
  if (!(shear_N_per_m_ > 0))
    throw std::invalid_argument("Material/Shear stiffness must be positive (N/m)");
  warp_in_s_ = warp_in_s(*this, data.warp_tension);
  // Small-strain weft stiffness of a strip held in the warp direction adds Psi2'' g'^2.
  const double g0 = lateral_contraction_slope(0.0);
  const double coupling = warp_in_s_.slope(0.0) * g0 * g0;
  for (double x : weft_.knots())
    stiffness_scale_ = std::max(stiffness_scale_, weft_.slope(x) + coupling);
  for (double x : warp_in_s_.knots())
    stiffness_scale_ = std::max(stiffness_scale_, warp_in_s_.slope(x));
}

double TensileCurves::lateral_contraction_slope(double e1) const {
  return lateral_contraction(Dual<1>::variable(e1, 0)).grad[0];
}

double TensileCurves::held_weft_tension(double e1) const {
  using D = Dual<1>;
  return energy(D::variable(e1, 0), D(0.0), D(0.0)).grad[0];
}

double TensileCurves::weft_strain_of_warp_strip(double tau) const {
  // f(e1) = T1(e1) + tau g'(e1) is >= 0 at e1 = 0 and falls to -inf on the left, where T1 goes
  // on as a straight line and g' is the first Poisson coefficient: bisect.
  const auto f = [&](double e1) { return weft_tension(e1) + tau * lateral_contraction_slope(e1); };
  double high = 0.0, low = -0.05;
  while (f(low) > 0.0) {
    high = low;
    low *= 2.0;
    if (low < -0.99)
      throw std::invalid_argument(
          "Material/Tension curve warp: the weft of a warp strip at tension " +
          std::to_string(tau) + " N/m would contract by more than 99%");
  }
  for (int i = 0; i < 200 && high - low > 1e-15; ++i) {
    const double mid = 0.5 * (low + high);
    (f(mid) > 0.0 ? high : low) = mid;
  }
  return 0.5 * (low + high);
}

}  // namespace tightfit
