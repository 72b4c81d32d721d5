#include "massspring/triangle_elements.h"

#include "massspring/positive_part.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tightfit {

TriangleElements::TriangleElements(const SimulationMesh& mesh, const MaterialLaw& law) : law_(law) {
  elements_.reserve(mesh.triangles.size());
  for (std::size_t k = 0; k < mesh.triangles.size(); ++k) {
    const auto& X = mesh.rest_triangles[k];
    Mat2 dX;
    dX.col(0) = X[1] - X[0];
    dX.col(1) = X[2] - X[0];
    const double doubled_area = dX.determinant();
    if (!(doubled_area > 0))
      throw std::invalid_argument("mass spring: triangle " + std::to_string(k) +
                                  " has no positive rest area (degenerate or clockwise panel)");
    // F = [x1 - x0, x2 - x0] dX^-1: the rows of dX^-1 are g1 and g2, and g0 = -(g1 + g2).
    const Mat2 inverse = dX.inverse();
    Element e;
    e.vertex = mesh.triangles[k];
    e.gradient[1] = inverse.row(0).transpose();
    e.gradient[2] = inverse.row(1).transpose();
    e.gradient[0] = -(e.gradient[1] + e.gradient[2]);
    e.rest_area_m2 = 0.5 * doubled_area;
    elements_.push_back(e);
  }
}

double TriangleElements::energy_J(const std::vector<Vec3>& x) const {
  double energy = 0.0;
  for (const Element& e : elements_) {
    const Mat32 F = deformation_gradient(e, x);
    energy += e.rest_area_m2 * law_.energy(F.transpose() * F);
  }
  return energy;
}

void TriangleElements::add_forces(const std::vector<Vec3>& x, std::vector<Vec3>& force_N) const {
  for (const Element& e : elements_) {
    const Mat32 F = deformation_gradient(e, x);
    // First Piola-Kirchhoff membrane stress P = F S (N/m), scaled by the rest area.
    const Mat32 AP = e.rest_area_m2 * (F * law_.stress(F.transpose() * F));
    for (int i = 0; i < 3; ++i) force_N[e.vertex[i]] -= AP * e.gradient[i];
  }
}

void TriangleElements::add_stiffness_bounds(const std::vector<Vec3>& x,
                                            std::vector<double>& stiffness_N_per_m) const {
  for (const Element& e : elements_) {
    const Mat32 F = deformation_gradient(e, x);
    const Mat2 C = F.transpose() * F;
    // d f_i / d x_j = -A0 [ (g_i^T S g_j) I + F-weighted material term ]; bound both by norms:
    // |material| <= ||D||_inf |F|^2 |g_i| |g_j|, |geometric| <= ||S|| |g_i| |g_j|.
    const Mat3 D = law_.tangent(C);
    const double material = D.cwiseAbs().rowwise().sum().maxCoeff() * F.squaredNorm();
    const double geometric = law_.stress(C).cwiseAbs().rowwise().sum().maxCoeff();
    const double modulus = std::max(material, law_.stiffness_scale()) + geometric;
    double gradient_sum = 0.0;
    for (int j = 0; j < 3; ++j) gradient_sum += e.gradient[j].norm();
    for (int i = 0; i < 3; ++i)
      stiffness_N_per_m[e.vertex[i]] +=
          e.rest_area_m2 * modulus * e.gradient[i].norm() * gradient_sum;
  }
}

}  // namespace tightfit

namespace tightfit {

void TriangleElements::add_stiffness(const std::vector<Vec3>& x, Triplets& triplets,
                                     bool projected) const {
  for (const Element& e : elements_) {
    const Mat32 F = deformation_gradient(e, x);
    const Mat2 C = F.transpose() * F;
    const Mat3 D = law_.tangent(C);
    const Mat2 S = law_.stress(C);
    // B_j: d[E11, E22, 2 E12] / dx_j, E = (F^T F - I) / 2 and dF = dx_j g_j^T.
    std::array<Mat3, 3> B;
    for (int j = 0; j < 3; ++j) {
      const Vec2& g = e.gradient[j];
      B[j].row(0) = g.x() * F.col(0).transpose();
      B[j].row(1) = g.y() * F.col(1).transpose();
      B[j].row(2) = g.y() * F.col(0).transpose() + g.x() * F.col(1).transpose();
    }
    Mat9 K;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const double geometric = e.gradient[i].dot(S * e.gradient[j]);
        K.block<3, 3>(3 * i, 3 * j) =
            e.rest_area_m2 * (B[i].transpose() * D * B[j] + geometric * Mat3::Identity());
      }
    // In tension (S and D positive semi-definite) both terms are, and K is left exact; a
    // compressed element's K takes its positive part (positive_part.h).
    if (projected && !(Eigen::SelfAdjointEigenSolver<Mat2>(S).eigenvalues().minCoeff() >= 0.0 &&
                       Eigen::SelfAdjointEigenSolver<Mat3>(D).eigenvalues().minCoeff() >= 0.0))
      clamp_to_positive_part(K);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        add_block(triplets, e.vertex[i], e.vertex[j], K.block<3, 3>(3 * i, 3 * j));
  }
}

}  // namespace tightfit
