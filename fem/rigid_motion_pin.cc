#include "fem/rigid_motion_pin.h"

#include <Eigen/Dense>

#include <cmath>
#include <limits>

namespace tightfit {

namespace {

using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Motion = Eigen::Matrix<double, 3, 6>;

// The velocity of point x under the six unit rigid motions: slides along x, y, z and turns
// about axes through c, the turns scaled by 1/L so that all six move the garment alike.
Motion rigid_velocities(const Vec3& x, const Vec3& c, double L) {
  Motion B;
  B.leftCols<3>().setIdentity();
  const Vec3 r = (x - c) / L;
  // omega x r = -[r]_x omega
  B.rightCols<3>() << 0, r.z(), -r.y(), -r.z(), 0, r.x(), r.y(), -r.x(), 0;
  return B;
}

}  // namespace

RigidMotionPin rigid_motion_pin(const RigidBody& body, const std::vector<Vec3>& positions_m,
                                const ConstrainedDirections& constrained, bool friction,
                                const Vec3* held_turn_axis) {
  RigidMotionPin result;
  const int n = static_cast<int>(positions_m.size());
  if (friction || n == 0) return result;
  Vec3 c = Vec3::Zero();
  for (const Vec3& x : positions_m) c += x / n;
  double L2 = 0.0;
  for (const Vec3& x : positions_m) L2 += (x - c).squaredNorm() / n;
  const double L = std::sqrt(L2);
  if (!(L > 0.0)) return result;

  // C = sum over the restraining directions d (body normals, constrained directions) of
  // (B^T d)(B^T d)^T: its null space is the free rigid motions.
  Matrix6 C = Matrix6::Zero();
  for (int w = 0; w < n; ++w) {
    const Motion B = rigid_velocities(positions_m[w], c, L);
    const auto add = [&](const Vec3& d) {
      const Eigen::Matrix<double, 6, 1> row = B.transpose() * d;
      C += row * row.transpose();
    };
    add(body.query(positions_m[w]).outward_normal);
    if (w < constrained.size())
      for (const Vec3& d : constrained.directions(w)) add(d);
  }
  // The held turn restrains the unit turn about its axis (the last three coordinates, scaled by
  // 1/L as in rigid_velocities) as much as the whole garment's restraints do.
  if (held_turn_axis) {
    Eigen::Matrix<double, 6, 1> turn = Eigen::Matrix<double, 6, 1>::Zero();
    turn.tail<3>() = held_turn_axis->normalized();
    C += C.trace() * turn * turn.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Matrix6> eigen(C);
  // Free: an eigenvalue at round-off against the largest (exact symmetries give 1e-16 of it).
  // A faceted body with a smooth normal field (docs/bodies.md) nearly keeps a cylinder's: the
  // 48-sided prism of tests/cases/test_tube_on_mesh_cylinder.cc gives 5e-8 for the turn and
  // 6e-4 for the slide. They are left free: the facets do restrain them, so a pin would bear a
  // reaction, and with the contact's exact tangent (MembraneAssembly) Newton converges
  // quadratically there without one.
  const double largest = eigen.eigenvalues().maxCoeff();
  std::vector<int> free;
  for (int m = 0; m < 6; ++m)
    if (eigen.eigenvalues()[m] <= 1e-10 * largest) free.push_back(m);
  result.n_free_motions = static_cast<int>(free.size());
  Eigen::MatrixXd Q(6, free.size());  // the free motions still to stop, orthonormal columns
  for (std::size_t k = 0; k < free.size(); ++k) Q.col(k) = eigen.eigenvectors().col(free[k]);

  std::vector<char> pinned(n, 0);
  while (Q.cols() > 0) {
    // The vertex nearest the centroid that the remaining motions move well: each motion it
    // can stop (one per direction, up to three) by at least a tenth of the unit motion.
    int best = -1, best_rank = 0;
    double best_distance = std::numeric_limits<double>::infinity();
    for (int w = 0; w < n; ++w) {
      if (pinned[w] || (w < constrained.size() && constrained.constrained(w))) continue;
      const Eigen::JacobiSVD<Eigen::MatrixXd> svd(rigid_velocities(positions_m[w], c, L) * Q);
      int rank = 0;
      for (int k = 0; k < svd.singularValues().size(); ++k) rank += svd.singularValues()[k] >= 0.1;
      const double distance = (positions_m[w] - c).norm();
      if (rank > best_rank || (rank == best_rank && rank > 0 && distance < best_distance - 1e-12)) {
        best = w;
        best_rank = rank;
        best_distance = distance;
      }
    }
    if (best < 0) break;  // every vertex constrained or pinned: nothing left to pin with
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(rigid_velocities(positions_m[best], c, L) * Q,
                                                Eigen::ComputeFullU | Eigen::ComputeFullV);
    RigidMotionPin::Pin pin;
    pin.vertex = best;
    for (int k = 0; k < best_rank; ++k) pin.directions.push_back(svd.matrixU().col(k));
    result.pins.push_back(pin);
    pinned[best] = 1;
    // The motions this pin does not stop: the right singular vectors past its rank.
    Q = Q * svd.matrixV().rightCols(Q.cols() - best_rank);
  }
  return result;
}

}  // namespace tightfit
