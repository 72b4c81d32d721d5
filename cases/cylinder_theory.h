// Closed-form pressure of a membrane tube on a rigid cylinder (shared/reference/
// cylinder-theory.md): the reference every backend is verified against.
#pragma once

#include "core/backend.h"
#include "core/material.h"

#include <string>

namespace tightfit {

// Pressure per current contact area, Pa, of a tube of rest radius R0 on a cylinder of radius
// alpha R0, for the law called `law_name` (make_material_law's names) and the end condition.
// Zero for alpha <= 1 (the tube does not touch). NaN where no uniform state exists (a
// St. Venant-Kirchhoff tube whose free ends would contract to nothing).
double closed_form_pressure_Pa(const std::string& law_name, EndCondition ends,
                               const FabricParameters& fabric, double rest_radius_m, double alpha);

// The paper's Eq. 7, P = E t (1 - 1/alpha) / R0, with E t the hoop (weft) stiffness.
double paper_eq7_pressure_Pa(double hoop_stiffness_N_per_m, double rest_radius_m, double alpha);

// Free-end axial stretch b (cylinder-theory.md, "Derivation of the free-end axial stretch");
// 1 for held ends.
double axial_stretch(const std::string& law_name, EndCondition ends, const FabricParameters& fabric,
                     double alpha);

const char* to_string(EndCondition ends);

}  // namespace tightfit
