#include "cases/cylinder_theory.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace tightfit {

const char* to_string(EndCondition ends) {
  return ends == EndCondition::free_ends ? "free" : "held";
}

double axial_stretch(const std::string& law_name, EndCondition ends, const FabricParameters& fabric,
                     double alpha) {
  if (ends == EndCondition::held_ends) return 1.0;
  const double nu12 = fabric.poisson_weft_warp, a = alpha;
  if (law_name == "linear biot") return 1.0 - nu12 * (a - 1.0);
  if (law_name == "st venant kirchhoff") {
    const double b_squared = 1.0 - nu12 * (a * a - 1.0);
    return b_squared > 0 ? std::sqrt(b_squared) : std::numeric_limits<double>::quiet_NaN();
  }
  if (law_name == "neo hookean") return 1.0 / std::sqrt(a);
  if (law_name == "tensile curves")
    return 1.0 - TensileCurves(fabric.tensile_curves()).lateral_contraction(a - 1.0);
  throw std::invalid_argument("no closed form for law '" + law_name + "'");
}

double closed_form_pressure_Pa(const std::string& law_name, EndCondition ends,
                               const FabricParameters& fabric, double rest_radius_m, double alpha) {
  if (alpha <= 1.0) return 0.0;
  const double a = alpha, R0 = rest_radius_m;
  const double Y1 = fabric.stiffness_weft_N_per_m;
  const double nu12 = fabric.poisson_weft_warp, nu21 = fabric.poisson_warp_weft();
  const bool held = ends == EndCondition::held_ends;
  if (law_name == "linear biot") {
    // Table "Results", rows 1-2.
    return held ? Y1 * (1.0 - 1.0 / a) / (R0 * (1.0 - nu12 * nu21))
                : Y1 * (1.0 - 1.0 / a) / (R0 * (1.0 - nu12 * (a - 1.0)));
  }
  if (law_name == "st venant kirchhoff") {
    // Rows 3-4.
    if (held) return Y1 * (a * a - 1.0) / (2.0 * R0 * (1.0 - nu12 * nu21));
    return Y1 * (a * a - 1.0) / (2.0 * R0 * axial_stretch(law_name, ends, fabric, a));
  }
  if (law_name == "neo hookean") {
    // Rows 5-6; row 5 is the paper's Eq. 8.
    const double Gt = fabric.neo_hookean_shear_modulus_Pa * fabric.thickness_m;
    return held ? Gt * (1.0 - std::pow(a, -4.0)) / R0
                : Gt * (std::sqrt(a) - std::pow(a, -2.5)) / R0;
  }
  if (law_name == "tensile curves") {
    // Free ends: the hoop is a free weft strip, N = T1(alpha - 1) read off the curve, and the
    // tube narrows by g(alpha - 1). Held ends: dW/de1 with the warp strain held at zero.
    const TensileCurves curves(fabric.tensile_curves());
    const double N = held ? curves.held_weft_tension(a - 1.0) : curves.weft_tension(a - 1.0);
    return N / (axial_stretch(law_name, ends, fabric, a) * a * R0);
  }
  throw std::invalid_argument("no closed form for law '" + law_name + "'");
}

double paper_eq7_pressure_Pa(double hoop_stiffness_N_per_m, double rest_radius_m, double alpha) {
  if (alpha <= 1.0) return 0.0;
  return hoop_stiffness_N_per_m * (1.0 - 1.0 / alpha) / rest_radius_m;
}

double tube_weight_per_area_Pa(double areal_density_kg_per_m2, double gravity_across_m_per_s2,
                               double alpha, double axial_stretch) {
  return areal_density_kg_per_m2 * gravity_across_m_per_s2 / (alpha * axial_stretch);
}

double gravity_top_minus_bottom_Pa(double weight_per_area_Pa, bool contact_traction) {
  return (contact_traction ? 4.0 : 2.0) * weight_per_area_Pa;
}

}  // namespace tightfit
