#include "fem/traction_recovery.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <stdexcept>

namespace tightfit {

std::vector<double> recover_traction_Pa(int n_nodes, const SurfaceQuadrature& quadrature,
                                        const std::vector<double>& load_N) {
  std::vector<Eigen::Triplet<double>> entries;
  for (std::size_t cell = 0; cell < quadrature.cell_nodes.size(); ++cell) {
    const std::vector<int>& nodes = quadrature.cell_nodes[cell];
    for (std::size_t q = 0; q < quadrature.shape_values.size(); ++q) {
      const std::vector<double>& N = quadrature.shape_values[q];
      const double dA_m2 = quadrature.point_area_m2[cell][q];
      for (std::size_t a = 0; a < nodes.size(); ++a)
        for (std::size_t b = 0; b < nodes.size(); ++b)
          entries.emplace_back(nodes[a], nodes[b], N[a] * N[b] * dA_m2);
    }
  }
  Eigen::SparseMatrix<double> mass_m2(n_nodes, n_nodes);
  mass_m2.setFromTriplets(entries.begin(), entries.end());
  // M is symmetric positive definite (the Gram matrix of independent functions).
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor(mass_m2);
  if (factor.info() != Eigen::Success)
    throw std::runtime_error("traction recovery: the surface mass matrix is singular");
  const Eigen::VectorXd f = Eigen::Map<const Eigen::VectorXd>(load_N.data(), n_nodes);
  const Eigen::VectorXd t = factor.solve(f);
  return std::vector<double>(t.data(), t.data() + n_nodes);
}

}  // namespace tightfit
