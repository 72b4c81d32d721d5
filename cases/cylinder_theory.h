// Closed-form pressure of a membrane tube on a rigid cylinder (docs/model.md, "Closed
// forms"): the reference every backend is verified against.
#pragma once

#include "core/material.h"

#include <string>

namespace tightfit {

// The closed forms' two end conditions for a tube.
enum class EndCondition {
  free_ends,  // no axial force at the tube's ends (the paper's assumption)
  held_ends,  // the end vertices keep their axial coordinate (axial stretch 1)
};

// Pressure per current contact area, Pa, of a tube of rest radius R0 on a cylinder of radius
// alpha R0, for the law called `law_name` (make_material_law's names) and the end condition.
// Zero for alpha <= 1 (the tube does not touch). NaN where no uniform state exists (a
// St. Venant-Kirchhoff tube whose free ends would contract to nothing).
double closed_form_pressure_Pa(const std::string& law_name, EndCondition ends,
                               const FabricParameters& fabric, double rest_radius_m, double alpha);

// The paper's Eq. 7, P = E t (1 - 1/alpha) / R0, with E t the hoop (weft) stiffness.
double paper_eq7_pressure_Pa(double hoop_stiffness_N_per_m, double rest_radius_m, double alpha);

// Free-end axial stretch b (docs/model.md, "Closed forms": no axial stress at the free
// ends); 1 for held ends.
double axial_stretch(const std::string& law_name, EndCondition ends, const FabricParameters& fabric,
                     double alpha);

const char* to_string(EndCondition ends);

// A tube on a horizontal frictionless cylinder under gravity (docs/closed-forms.md, "A tube on a
// cylinder under gravity"). Its weight per unit current area, Pa: the rest areal density spread
// over the stretched area, w = rho_A g / (alpha b), with g the component of gravity across the
// axis and b the axial stretch.
double tube_weight_per_area_Pa(double areal_density_kg_per_m2, double gravity_across_m_per_s2,
                               double alpha, double axial_stretch);
// With theta the angle from the top, the pressure reads p(theta) = p0 + k w cos(theta), p0 the
// closed form without gravity: k = 2 for the contact traction (the weight pressing at the top
// and hanging at the bottom, plus the hoop tension it changes), k = 1 for the garment's own
// force (the paper's definition, which sees the tension alone). Top minus bottom: 2 k w.
double gravity_top_minus_bottom_Pa(double weight_per_area_Pa, bool contact_traction);

}  // namespace tightfit
