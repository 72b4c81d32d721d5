// Grid-convergence arithmetic: observed order, Richardson extrapolation and Roache's grid
// convergence index (GCI), from values computed on meshes refined by a constant ratio.
//
// Conventions used throughout: f_fine, f_medium, f_coarse are one quantity (a mean pressure,
// say) on meshes of edge length h, r h and r^2 h; `ratio` r > 1 is the refinement ratio
// (2 when each level halves the edge length). Functions return NaN where the answer is not
// defined (non-monotone sequences, equal values, errors of zero) instead of throwing, so a
// study can write the row and carry on. Plain arithmetic: no deal.II, no mesh.
#pragma once

#include <optional>
#include <vector>

namespace tightfit {

// Roache's safety factor: 1.25 when the order was observed from three or more meshes, 3 when
// only two meshes were computed and the order is assumed (Roache 1994, J. Fluids Eng. 116;
// Roache 1998, "Verification and Validation in Computational Science and Engineering").
double gci_safety_factor(int n_meshes);

// Observed order p = ln((f_coarse - f_medium) / (f_medium - f_fine)) / ln r (Roache 1998,
// Ch. 5, for a constant ratio r). NaN when the differences change sign (oscillatory
// convergence) or one of them is zero.
double observed_order(double f_coarse, double f_medium, double f_fine, double ratio);

// Richardson-extrapolated value f_fine + (f_fine - f_medium) / (r^p - 1): the h -> 0 limit
// when the error is C h^p (Richardson 1911; Roache 1998,
// Ch. 5). NaN for a non-finite or
// non-positive order.
double richardson_extrapolate(double f_medium, double f_fine, double ratio, double order);

// GCI of the fine mesh, as a fraction of |f_fine|: F_s |(f_medium - f_fine) / f_fine| /
// (r^p - 1) (Roache 1994). An error band: the h -> 0 value lies within
// f_fine (1 +- GCI) with about 95% confidence for F_s = 1.25. NaN when f_fine is zero or the
// order is not positive.
double grid_convergence_index(double f_medium, double f_fine, double ratio, double order,
                              double safety_factor);

// Order of the error against a known exact value, from two meshes:
// p = ln(|e_coarse| / |e_fine|) / ln r. NaN when either error is zero.
double error_order(double error_coarse, double error_fine, double ratio);

// What a study concludes about one quantity from its values on every mesh.
struct ConvergenceEstimate {
  int n_meshes = 0;
  double order = 0.0;           // observed from the finest three; else the assumed order
  bool order_observed = false;  // false: two meshes, the order is the assumed one
  double extrapolated = 0.0;    // Richardson value with `order`
  double gci_fine = 0.0;        // GCI of the finest mesh, fraction of |f_fine|
  double safety_factor = 0.0;
  double error_order = 0.0;  // order of |f - exact| from the finest two; NaN without exact
};

// `values` ordered coarse to fine (at least two; throws std::invalid_argument otherwise),
// each mesh `ratio` times finer than the one before. With three or more meshes the finest
// three give the observed order; with two, `assumed_order` (the element's formal order) is
// used with safety factor 3. `exact` is the closed form, when one exists.
ConvergenceEstimate estimate_convergence(const std::vector<double>& values, double ratio,
                                         double assumed_order, std::optional<double> exact);

}  // namespace tightfit
