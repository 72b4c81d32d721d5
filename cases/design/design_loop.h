// Designing a tubular garment to a pressure profile (docs/design.md): the unknowns are its
// relaxed circumference c_k at each measuring point k, the answer each band's mean simulated
// pressure.
//
// First guess, Laplace's law on the limb's girth g_k (r = g / 2 pi): the ring of relaxed
// circumference c is stretched lambda = g / c round the limb and presses
//
//   p_L(c) = N(g / c) 2 pi / g                                                   (1)
//
// with N the fabric's hoop force per unit rest width (cases/design/hoop_force.h); c_0 solves
// p_L(c) = target. Then each iteration simulates, and corrects every band with the ratio
// kappa_k = p_sim / p_L(c_k) the simulation measured there: the next c_k solves
// kappa_k p_L(c) = target (a Newton step on Laplace's curve scaled to the simulation, which
// keeps the shape's share of the pressure, kappa, fixed), until every band is within the
// tolerance.
#pragma once

#include "cases/design/design_target.h"
#include "cases/design/hoop_force.h"

#include <functional>
#include <string>
#include <vector>

namespace tightfit {

// Eq. (1), Pa.
double laplace_pressure_Pa(const HoopForce& hoop, double girth_m, double circumference_m);

// The circumference for which Eq. (1) gives `pressure_Pa`, m. Throws std::invalid_argument
// naming the band, the pressure, the strain range and the most the fabric gives there, when no
// strain within the range gives it (`why` says what the pressure is: "the target", ...).
double laplace_circumference_m(const HoopForce& hoop, const std::string& band, double girth_m,
                               double pressure_Pa, const std::string& why = "the target");

struct BandPressure {
  double mean_Pa = 0.0;  // over the band's contact area
  double peak_Pa = 0.0;
};

struct DesignBand {
  double circumference_m = 0.0;
  double laplace_Pa = 0.0;
  double mean_Pa = 0.0;
  double peak_Pa = 0.0;
};

struct DesignIteration {
  int number = 0;  // 1, 2, ...: the simulations run
  std::vector<DesignBand> bands;
  double seconds = 0.0;  // wall time of the simulation
  bool met = false;      // every band within the tolerance
};

struct DesignProblem {
  std::vector<NamedValue> points;  // name, height along the garment (m)
  std::vector<double> girths_m;    // the limb's girth at each point
  std::vector<double> targets_Pa;  // the mean pressure wanted over each point's band
  double tolerance_Pa = 0.5 * 133.322387415;
  int maximum_iterations = 6;
};

// Simulates the garment cut to `circumferences_m` (one per point) and returns each band's
// pressure; `iteration` numbers the call from 1.
using DesignSimulation = std::function<std::vector<BandPressure>(
    const std::vector<double>& circumferences_m, int iteration)>;

struct DesignResult {
  std::vector<DesignIteration> iterations;
  bool met = false;
};

// Laplace's first guess at every point. Throws as laplace_circumference_m for a target the
// fabric cannot give.
std::vector<double> laplace_first_guess(const DesignProblem& problem, const HoopForce& hoop);

// Iterates from the first guess until every band is within the tolerance or the iterations
// run out; `on_iteration` sees each one as it finishes. Throws std::invalid_argument when a
// correction asks a strain beyond the fabric's range (naming the band).
DesignResult run_design(const DesignProblem& problem, const HoopForce& hoop,
                        const DesignSimulation& simulate,
                        const std::function<void(const DesignIteration&)>& on_iteration = {});

}  // namespace tightfit
