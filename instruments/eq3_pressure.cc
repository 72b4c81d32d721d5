#include "instruments/eq3_pressure.h"

#include <Eigen/Eigenvalues>

namespace tightfit {

Eq3Estimate eq3_pressure(const StampFit& fit, const MaterialLaw& law, const RigidBody& body) {
  const Mat32& F = fit.deformation_gradient;
  const Mat2 C = F.transpose() * F;
  // Membrane Cauchy stress (N per current length): sigma = F S F^T / J, J the area stretch.
  const double J = std::sqrt(C.determinant());
  const Mat3 sigma = F * law.stress(C) * F.transpose() / J;
  // Its eigenvectors in the tangent plane: the two largest in magnitude of the rank-2 tensor
  // are found in the plane spanned by F's columns.
  const Vec3 a = F.col(0).normalized();
  const Vec3 b = (F.col(1) - F.col(1).dot(a) * a).normalized();
  Eigen::Matrix<double, 3, 2> Q;
  Q << a, b;
  const Eigen::SelfAdjointEigenSolver<Mat2> eigen(Q.transpose() * sigma * Q);
  Eq3Estimate e;
  e.tension_min_N_per_m = eigen.eigenvalues()[0];
  e.tension_max_N_per_m = eigen.eigenvalues()[1];
  e.direction_min = Q * eigen.eigenvectors().col(0);
  e.direction_max = Q * eigen.eigenvectors().col(1);
  // The body's curvature at its own surface (zero gap): dn/dx along a tangent direction d.
  const SurfacePoint surface = body.query(body.query(fit.centre_m).closest_point_m);
  const Mat3& dn = surface.normal_derivative_per_m;
  e.curvature_max_per_m = e.direction_max.dot(dn * e.direction_max);
  e.curvature_min_per_m = e.direction_min.dot(dn * e.direction_min);
  e.pressure_Pa =
      e.tension_max_N_per_m * e.curvature_max_per_m + e.tension_min_N_per_m * e.curvature_min_per_m;
  return e;
}

}  // namespace tightfit
