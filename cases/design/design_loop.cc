#include "cases/design/design_loop.h"

#include "core/units.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace tightfit {

double laplace_pressure_Pa(const HoopForce& hoop, double girth_m, double circumference_m) {
  return hoop.force(girth_m / circumference_m) * 2 * M_PI / girth_m;
}

double laplace_circumference_m(const HoopForce& hoop, const std::string& band, double girth_m,
                               double pressure_Pa, const std::string& why) {
  const double force = pressure_Pa * girth_m / (2 * M_PI);
  const double stretch = hoop.stretch_for(force);
  if (std::isnan(stretch)) {
    char text[400];
    std::snprintf(text, sizeof text,
                  "band %s: %s, %.2f mmHg on a girth of %.2f cm, asks a hoop force of %.3g N/m; "
                  "within the fabric's strain range (0 to %.3g) its hoop force runs from 0 to "
                  "%.3g N/m, at most %.2f mmHg on this girth",
                  band.c_str(), why.c_str(), units::to_mmHg(pressure_Pa), 100 * girth_m, force,
                  hoop.largest_strain(), hoop.largest_force(),
                  units::to_mmHg(hoop.largest_force() * 2 * M_PI / girth_m));
    throw std::invalid_argument(text);
  }
  return girth_m / stretch;
}

std::vector<double> laplace_first_guess(const DesignProblem& problem, const HoopForce& hoop) {
  std::vector<double> c;
  for (std::size_t k = 0; k < problem.points.size(); ++k)
    c.push_back(laplace_circumference_m(hoop, problem.points[k].name, problem.girths_m[k],
                                        problem.targets_Pa[k]));
  return c;
}

DesignResult run_design(const DesignProblem& problem, const HoopForce& hoop,
                        const DesignSimulation& simulate,
                        const std::function<void(const DesignIteration&)>& on_iteration) {
  const std::size_t n = problem.points.size();
  if (problem.girths_m.size() != n || problem.targets_Pa.size() != n)
    throw std::invalid_argument("a design needs one girth and one target per point");
  DesignResult result;
  std::vector<double> c = laplace_first_guess(problem, hoop);
  for (int number = 1; number <= problem.maximum_iterations; ++number) {
    const auto start = std::chrono::steady_clock::now();
    const std::vector<BandPressure> simulated = simulate(c, number);
    DesignIteration it;
    it.number = number;
    it.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    it.met = true;
    for (std::size_t k = 0; k < n; ++k) {
      DesignBand b;
      b.circumference_m = c[k];
      b.laplace_Pa = laplace_pressure_Pa(hoop, problem.girths_m[k], c[k]);
      b.mean_Pa = simulated.at(k).mean_Pa;
      b.peak_Pa = simulated.at(k).peak_Pa;
      // A band without contact (NaN) is not met.
      if (!(std::abs(b.mean_Pa - problem.targets_Pa[k]) <= problem.tolerance_Pa)) it.met = false;
      it.bands.push_back(b);
    }
    result.iterations.push_back(it);
    if (on_iteration) on_iteration(it);
    if (it.met) {
      result.met = true;
      return result;
    }
    if (number == problem.maximum_iterations) break;
    for (std::size_t k = 0; k < n; ++k) {
      const DesignBand& b = it.bands[k];
      const std::string& name = problem.points[k].name;
      if (!(b.mean_Pa > 0))
        throw std::invalid_argument("band " + name +
                                    ": the garment does not touch the limb there "
                                    "(no contact in the band): the design cannot be corrected");
      // kappa: the simulation's pressure over Laplace's at this band, kept for the next step.
      const double kappa = b.mean_Pa / b.laplace_Pa;
      c[k] = laplace_circumference_m(hoop, name, problem.girths_m[k], problem.targets_Pa[k] / kappa,
                                     "the target over the simulation's ratio to Laplace's law");
    }
  }
  return result;
}

}  // namespace tightfit
