// Membrane material laws, shared by every backend.
//
// Every law is a strain-energy density W(C) per unit *reference* area (J/m^2) of the 2x2 right
// Cauchy-Green tensor C = F^T F, expressed in the panel's material axes: x along the weft
// (course), y along the warp (wale). Anisotropy is therefore free: the law sees the grain.
// Stiffnesses are membrane stiffnesses Y = E t in N/m (the paper's "Et"; 1 N/cm = 100 N/m).
#pragma once

#include "core/tensile_curves.h"
#include "core/types.h"

#include <memory>
#include <string>
#include <vector>

namespace tightfit {

// The fabric: the paper's Table 2 by default.
struct FabricParameters {
  // Y1 = E t along the weft / course (x axis), N/m. Table 2: 1.3 N/cm.
  double stiffness_weft_N_per_m = 130.0;
  // Y2 = E t along the warp / wale (y axis), N/m. Table 2: 0.7 N/cm.
  double stiffness_warp_N_per_m = 70.0;
  // nu12: contraction along the warp per unit stretch along the weft. Table 2 (1000 g): 0.2021.
  double poisson_weft_warp = 0.2021;
  // In-plane shear stiffness G12 t, N/m. Not measured in the paper; a knit's shear is soft.
  double shear_stiffness_N_per_m = 30.0;
  // Rest thickness t0, m. Table 2: 0.039 cm.
  double thickness_m = 0.39e-3;
  // Mass per reference area, kg/m^2. Table 2: 1.057e-5 kg/cm^2.
  double areal_density_kg_per_m2 = 0.1057;
  // Shear modulus of the incompressible neo-Hookean law, Pa. Default: the small-strain match
  // 3 G t0 = mean of Y1 and Y2 = 100 N/m, so G = 100 / (3 * 0.39e-3) Pa.
  double neo_hookean_shear_modulus_Pa = 100.0 / (3.0 * 0.39e-3);

  // The 'tensile curves' law (core/tensile_curves.h): force per unit rest width against
  // engineering strain along each direction, and nu12 against weft strain. Defaults: Table 2's
  // two loads and the origin (course = weft: 0.35 and 0.60 at 0.245 and 0.49 N/cm; wale = warp:
  // 0.575 and 0.825), the Poisson coefficient 0.3499 at the lower load and 0.2021 at the higher.
  std::vector<CurvePoint> tension_curve_weft = {{0.0, 0.0}, {0.35, 24.5}, {0.60, 49.0}};
  std::vector<CurvePoint> tension_curve_warp = {{0.0, 0.0}, {0.575, 24.5}, {0.825, 49.0}};
  std::vector<CurvePoint> poisson_curve = {{0.35, 0.3499}, {0.60, 0.2021}};

  // The tensile-curve description of this fabric.
  TensileCurveData tensile_curves() const {
    return {tension_curve_weft, tension_curve_warp, poisson_curve, shear_stiffness_N_per_m};
  }

  // nu21 from the symmetry of the compliance: nu12 * Y2 = nu21 * Y1.
  double poisson_warp_weft() const {
    return poisson_weft_warp * stiffness_warp_N_per_m / stiffness_weft_N_per_m;
  }
  // Throws std::invalid_argument naming the offending entry when a value is unphysical.
  void validate() const;
};

class MaterialLaw {
 public:
  virtual ~MaterialLaw() = default;
  virtual std::string name() const = 0;

  // W(C), J/m^2 of reference area.
  virtual double energy(const Mat2& C) const = 0;
  // Second Piola-Kirchhoff membrane stress S = 2 dW/dC, N/m (symmetric).
  virtual Mat2 stress(const Mat2& C) const = 0;
  // Material tangent dS/dE in Voigt order (11, 22, 12), E = (C - I)/2, engineering shear:
  // dS = D [dE11, dE22, 2 dE12]^T. Symmetric, N/m.
  virtual Mat3 tangent(const Mat2& C) const = 0;
  // The largest small-strain membrane stiffness, N/m: the tension scale of stop rules.
  virtual double stiffness_scale() const = 0;
};

// Names accepted by make_material_law, in the order shown to users.
std::vector<std::string> material_law_names();
// One line per law for --print-parameters.
std::string material_law_descriptions();
// Creates the law called `name` ("linear biot", "st venant kirchhoff", "neo hookean",
// "tensile curves").
// Throws std::invalid_argument listing the known names when `name` is unknown.
std::unique_ptr<MaterialLaw> make_material_law(const std::string& name,
                                               const FabricParameters& fabric);

// The law `name` relaxed for slack (docs/model.md, "Slack: the tension field"): equal to it
// wherever both principal stresses are tensile, zero stress across wrinkles and no energy where
// the fabric is shortened every way, plus `compression_fraction` (0 to 1, dimensionless) of the
// law's own energy difference there. Throws std::invalid_argument for laws it does not relax
// (all but "linear biot") and a fraction outside [0, 1].
std::unique_ptr<MaterialLaw> make_tension_field_law(const std::string& name,
                                                    const FabricParameters& fabric,
                                                    double compression_fraction);

}  // namespace tightfit
