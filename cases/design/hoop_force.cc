#include "cases/design/hoop_force.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace tightfit {

HoopForce::HoopForce(std::shared_ptr<const MaterialLaw> law, HoopStrip strip, double largest_strain)
    : law_(std::move(law)), strip_(strip), largest_strain_(largest_strain) {
  if (!law_) throw std::invalid_argument("HoopForce: no material law");
  if (!(largest_strain_ > 0))
    throw std::invalid_argument("the largest hoop strain must be positive, not " +
                                std::to_string(largest_strain_));
}

double HoopForce::free_cross_stretch(double stretch) const {
  // S22 rises with the cross stretch (a positive-definite law): bisect it to zero between a
  // strip narrowed to a tenth and one widened by half.
  const auto s22 = [&](double cross) {
    Mat2 C = Mat2::Zero();
    C(0, 0) = stretch * stretch;
    C(1, 1) = cross * cross;
    return law_->stress(C)(1, 1);
  };
  double low = 0.1, high = 1.5;
  if (!(s22(low) < 0 && s22(high) > 0)) return 1.0;  // no root in range: the held strip's
  for (int k = 0; k < 80; ++k) {
    const double mid = 0.5 * (low + high);
    (s22(mid) < 0 ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

double HoopForce::force(double stretch) const {
  if (!(stretch > 1.0)) return 0.0;
  const double cross = strip_ == HoopStrip::free ? free_cross_stretch(stretch) : 1.0;
  Mat2 C = Mat2::Zero();
  C(0, 0) = stretch * stretch;
  C(1, 1) = cross * cross;
  return stretch * law_->stress(C)(0, 0);  // P11 = F11 S11
}

double HoopForce::slope(double stretch) const {
  const double h = 1e-6;
  return (force(stretch + h) - force(stretch - h)) / (2 * h);
}

double HoopForce::stretch_for(double force_N_per_m) const {
  const double top = 1.0 + largest_strain_;
  if (!(force_N_per_m > 0) || force_N_per_m > force(top))
    return std::numeric_limits<double>::quiet_NaN();
  double low = 1.0, high = top;  // the force rises with the stretch (a positive-definite law)
  for (int k = 0; k < 100 && high - low > 1e-14; ++k) {
    const double mid = 0.5 * (low + high);
    (force(mid) < force_N_per_m ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

double known_largest_strain(const std::string& law_name, const FabricParameters& fabric,
                            double stated_largest_strain) {
  if (law_name == "tensile curves" && !fabric.tension_curve_weft.empty())
    return fabric.tension_curve_weft.back().strain;
  return stated_largest_strain;
}

}  // namespace tightfit
