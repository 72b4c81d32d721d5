#include "contact/residual_location.h"

#include <cmath>
#include <sstream>

namespace tightfit {

ResidualLocation locate_residual(const std::vector<Vec3>& positions_m,
                                 const std::vector<Vec3>& residual_N, const RigidBody* body) {
  ResidualLocation where;
  double largest_squared = -1.0, total_squared = 0.0;
  for (std::size_t i = 0; i < residual_N.size(); ++i) {
    const double squared = residual_N[i].squaredNorm();
    where.net_force_N += residual_N[i];
    total_squared += squared;
    if (squared > largest_squared) {
      largest_squared = squared;
      where.vertex = static_cast<int>(i);
    }
  }
  if (where.vertex < 0) return where;
  where.rms_N = std::sqrt(total_squared / residual_N.size());
  const Vec3& f = residual_N[where.vertex];
  where.position_m = positions_m[where.vertex];
  where.largest_N = f.norm();
  if (body) {
    const SurfacePoint s = body->query(where.position_m);
    where.gap_m = s.signed_distance_m;
    where.normal_N = f.dot(s.outward_normal);
    where.tangential_N = (f - where.normal_N * s.outward_normal).norm();
  }
  return where;
}

std::string text(const ResidualLocation& where) {
  if (where.vertex < 0) return "no vertex";
  const auto triple = [](const Vec3& v) {
    std::ostringstream out;
    out << "(" << v.x() << ", " << v.y() << ", " << v.z() << ")";
    return out.str();
  };
  std::ostringstream out;
  out << "largest residual " << where.largest_N << " N on vertex " << where.vertex << " at "
      << triple(where.position_m) << " m, gap " << where.gap_m << " m (along the body's normal "
      << where.normal_N << " N, across it " << where.tangential_N << " N); rms " << where.rms_N
      << " N; net force on the garment " << triple(where.net_force_N) << " N";
  return out.str();
}

}  // namespace tightfit
