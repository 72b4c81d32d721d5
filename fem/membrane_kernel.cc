#include "fem/membrane_kernel.h"

namespace tightfit {

void add_membrane_point(const MaterialLaw& law, const std::vector<Vec2>& grad_N_grain,
                        const Mat32& F, double JxW_m2, Eigen::VectorXd& energy_gradient_N,
                        Eigen::MatrixXd* tangent_N_per_m) {
  const int n_nodes = static_cast<int>(grad_N_grain.size());
  const Mat2 C = F.transpose() * F;
  const Mat2 S = law.stress(C);
  // Virtual work of the membrane: dPi = S : dE with dE = sym(F^T dF), dF = dx_a grad_N_a^T.
  for (int a = 0; a < n_nodes; ++a)
    energy_gradient_N.segment<3>(3 * a) += JxW_m2 * (F * (S * grad_N_grain[a]));
  if (!tangent_N_per_m) return;

  // Linearised Green strain of node a in Voigt order (11, 22, 2*12): rows of B_a (3x3).
  std::vector<Mat3> B(n_nodes);
  for (int a = 0; a < n_nodes; ++a) {
    const Vec2& g = grad_N_grain[a];
    B[a].row(0) = g.x() * F.col(0).transpose();
    B[a].row(1) = g.y() * F.col(1).transpose();
    B[a].row(2) = g.y() * F.col(0).transpose() + g.x() * F.col(1).transpose();
  }
  const Mat3 D = law.tangent(C);
  // Material part B^T D B plus the geometric (initial-stress) part (grad_N_a . S grad_N_b) I.
  for (int a = 0; a < n_nodes; ++a)
    for (int b = 0; b < n_nodes; ++b) {
      const double geometric = grad_N_grain[a].dot(S * grad_N_grain[b]);
      tangent_N_per_m->block<3, 3>(3 * a, 3 * b) +=
          JxW_m2 * (B[a].transpose() * D * B[b] + geometric * Mat3::Identity());
    }
}

}  // namespace tightfit
