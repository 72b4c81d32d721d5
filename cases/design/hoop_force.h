// The hoop force of a ring of fabric at a given hoop stretch: what Laplace's law needs to turn a
// relaxed circumference into a pressure (docs/design.md, "Laplace's law").
//
// The force is read off the case's own material law, per unit rest width (N/m), at the stretch
// lambda = girth / relaxed circumference round the course (weft, x): N = P11 = lambda S11 with
// S = 2 dW/dC the law's second Piola-Kirchhoff stress at F = diag(lambda, lambda2). The strip
// across the hoop is either
//   - free (a tensile test of the course: S22 = 0, lambda2 the strip's own contraction), the
//     force the fabric's course curve gives: for Material/Law = tensile curves exactly its
//     weft curve T1(lambda - 1);
//   - held at its rest length along the limb (lambda2 = 1), as a stocking held along the leg.
// The strains the fabric is known at run from 0 to its largest strain: the weft curve's last
// knot for the tensile-curves law, a stated bound for the laws with a constant stiffness.
#pragma once

#include "core/material.h"

#include <memory>
#include <string>

namespace tightfit {

enum class HoopStrip { free, held };

class HoopForce {
 public:
  // Throws std::invalid_argument for a largest strain that is not positive.
  HoopForce(std::shared_ptr<const MaterialLaw> law, HoopStrip strip, double largest_strain);

  // N/m per unit rest width at hoop stretch lambda (>= 1: a ring no longer than its girth
  // carries nothing a body feels, so stretches below 1 read 0).
  double force(double stretch) const;
  // dN/dlambda by a central difference, N/m.
  double slope(double stretch) const;
  // The stretch in [1, 1 + largest strain] at which the force is `force_N_per_m`; NaN when the
  // force lies beyond the range (the force at the largest strain is largest_force()).
  double stretch_for(double force_N_per_m) const;

  double largest_strain() const { return largest_strain_; }
  double largest_force() const { return force(1.0 + largest_strain_); }
  HoopStrip strip() const { return strip_; }

 private:
  // The cross stretch of a free strip at hoop stretch lambda (S22 = 0).
  double free_cross_stretch(double stretch) const;

  std::shared_ptr<const MaterialLaw> law_;
  HoopStrip strip_;
  double largest_strain_;
};

// The strain range the case's fabric is known over: the weft curve's last strain for the
// tensile-curves law, `stated_largest_strain` for the others.
double known_largest_strain(const std::string& law_name, const FabricParameters& fabric,
                            double stated_largest_strain);

}  // namespace tightfit
