#include "massspring/damped_rk4.h"

#include <cmath>

namespace tightfit {

double DampedRk4::frame(std::vector<Vec3>& x, std::vector<Vec3>& v,
                        const std::vector<double>& mass_kg, double dt, double c,
                        const Forces& forces, const Stable& stable) {
  const std::size_t n = x.size();
  if (force_.size() != n)
    for (auto* buffer : {&force_, &stage_x_, &stage_v_, &sum_x_, &sum_v_})
      buffer->assign(n, Vec3::Zero());
  const double stage_step[3] = {0.5 * dt, 0.5 * dt, dt};
  const double weight[4] = {1.0, 2.0, 2.0, 1.0};
  double measure = 0.0;
  for (int stage = 0; stage < 4; ++stage) {
    const std::vector<Vec3>& xs = stage == 0 ? x : stage_x_;
    const std::vector<Vec3>& vs = stage == 0 ? v : stage_v_;
    const double r = forces(xs, vs, force_);
    if (stage == 0) {
      measure = r;
      if (!std::isfinite(r) || (stable && stable(r))) return r;
    }
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3 velocity = vs[i];
      const Vec3 acceleration = force_[i] / mass_kg[i] - c * velocity;
      if (stage == 0) {
        sum_x_[i] = velocity;
        sum_v_[i] = acceleration;
      } else {
        sum_x_[i] += weight[stage] * velocity;
        sum_v_[i] += weight[stage] * acceleration;
      }
      if (stage < 3) {
        stage_x_[i] = x[i] + stage_step[stage] * velocity;
        stage_v_[i] = v[i] + stage_step[stage] * acceleration;
      }
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    x[i] += (dt / 6.0) * sum_x_[i];
    v[i] += (dt / 6.0) * sum_v_[i];
  }
  return measure;
}

}  // namespace tightfit
