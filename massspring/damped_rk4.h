// The paper's integrator (Section 2.1): classical fourth-order Runge-Kutta on
// y = (x, v), y' = (v, f(x)/m - c v), with mass-proportional damping c. Shared by the load
// steps and the flat-panel start, which differ only in their forces and stop rules.
#pragma once

#include "core/types.h"

#include <functional>
#include <vector>

namespace tightfit {

class DampedRk4 {
 public:
  // Fills `force` (N) for positions `x` and velocities `v` and returns a scalar measure of it
  // (the residual a stop rule reads; forces that depend on v, dampers, are best left out of it).
  using Forces = std::function<double(const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                                      std::vector<Vec3>& force)>;

  // Whether the state whose force measure the first stage has just returned is stable; read
  // right after that stage, so it may compare the measure with a threshold of the same state.
  using Stable = std::function<bool(double measure)>;

  // Advances (x, v) by one frame of dt_s and returns the force measure at the frame's start.
  // When `stable` (if given) holds at the frame's start or the measure is not finite, x and v are
  // left as they are: the state is already stable (or broken) and the caller decides.
  double frame(std::vector<Vec3>& x, std::vector<Vec3>& v, const std::vector<double>& mass_kg,
               double dt_s, double damping_per_s, const Forces& forces,
               const Stable& stable = nullptr);

 private:
  // Work space, allocated at the first frame (and again only if the particle count changes): the
  // stages accumulate into sum_x_, sum_v_ with weights 1, 2, 2, 1, so no per-stage copies are kept.
  std::vector<Vec3> force_, stage_x_, stage_v_, sum_x_, sum_v_;
};

}  // namespace tightfit
