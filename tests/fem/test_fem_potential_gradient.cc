// The potential Newton's line search judges steps by (MembraneAssembly::energy_J, docs/backends.md,
// "Newton's line search"): its gradient by central differences against the assembled residual R
// (FemBackend::linearise), with the contact inactive and active, on an analytic cylinder, where R
// is that gradient; and on a faceted cylinder, where the contact force takes the body's smooth
// normal and the potential the flat faces' distance, the gap between the two against
// FemBackend::potential_defect_N, the closed form of that difference.
#include "bodies/mesh_body.h"
#include "fem/fem_backend.h"
#include "tests/bodies/body_mesh_files.h"
#include "tube_problem.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <vector>

namespace tightfit {
namespace {

// Central differences of the potential at every node and direction, step h (m), against R;
// `body` decides which nodes lie within 10 h of the contact's kink (g = 0), whose differences
// straddle the penalty's switch and are left out. Fills the 2-norm of R - grad E (N) and of R.
struct GradientCheck {
  double difference_N = 0.0;  // || R - grad_fd E ||_2 over the nodes checked
  double residual_N = 0.0;    // || R ||_2 over the same nodes
  int n_in_contact = 0, n_skipped = 0, n_checked = 0;
};

GradientCheck check_gradient(const FemBackend& backend, const RigidBody& body,
                             const std::vector<Vec3>& x, double h_m) {
  Eigen::VectorXd R;
  Eigen::MatrixXd K;
  backend.linearise(x, R, K);
  GradientCheck check;
  double difference_squared = 0.0, residual_squared = 0.0;
  std::vector<Vec3> y = x;
  for (std::size_t k = 0; k < x.size(); ++k) {
    const double g = body.query(x[k]).signed_distance_m;
    if (std::abs(g) < 10.0 * h_m) {
      ++check.n_skipped;
      continue;
    }
    check.n_in_contact += g < 0.0;
    ++check.n_checked;
    for (int d = 0; d < 3; ++d) {
      y[k][d] = x[k][d] + h_m;
      const double plus = backend.energy_J(y, false);
      y[k][d] = x[k][d] - h_m;
      const double minus = backend.energy_J(y, false);
      y[k][d] = x[k][d];
      const double gradient_N = (plus - minus) / (2.0 * h_m);
      difference_squared += std::pow(R[3 * k + d] - gradient_N, 2);
      residual_squared += R[3 * k + d] * R[3 * k + d];
    }
  }
  check.difference_N = std::sqrt(difference_squared);
  check.residual_N = std::sqrt(residual_squared);
  return check;
}

// The tube "T" 6 cm high (two panels 15.7 cm wide, 2 cm x 1.5 cm edges, 80 vertices; linear
// Biot, free ends) placed at 1.2 times its rest radius, each vertex moved radially by up to
// +-0.2 mm: stretched 20 %, so the membrane pulls every node.
struct StretchedTube {
  testing::TubeCase tube{"linear biot", EndCondition::free_ends,
                         make_tube_garment("T", 0.157, 0.06, 2, MeshSpacing{0.02, 0.015})};
  std::vector<Vec3> x;

  StretchedTube() {
    x = tube.placed(1.2 * tube.rest_radius_m);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> radial(-2e-4, 2e-4);
    for (Vec3& p : x) {
      const Vec3 out(p.x(), p.y(), 0.0);
      p += radial(random) * out.normalized();
    }
  }
};

TEST(FemPotentialGradient, IsTheResidualOnACylinderInAndOutOfContact) {
  StretchedTube stretched;
  testing::TubeCase& tube = stretched.tube;
  FemBackend backend(tube.problem, FemParameters{});
  backend.set_positions(stretched.x);
  // The multipliers are 0 until a step is solved: the contact force is the penalty's, kA max(0,
  // -g) n. Step 1e-7 m: the energy (about 1e-2 J) keeps 9 digits of the difference.
  const double h_m = 1e-7;

  // Out of contact: the cylinder 1 cm inside the tube.
  tube.cylinder->set_radius(1.2 * tube.rest_radius_m - 0.01);
  const GradientCheck free = check_gradient(backend, *tube.cylinder, stretched.x, h_m);
  // In contact where the vertex lies inside the cylinder, grown to the tube's mean radius: about
  // half the nodes, each pressed up to 0.2 mm in (kA g up to newtons against the membrane's
  // tenths of a newton).
  tube.cylinder->set_radius(1.2 * tube.rest_radius_m);
  const GradientCheck pressed = check_gradient(backend, *tube.cylinder, stretched.x, h_m);
  for (const GradientCheck* c : {&free, &pressed})
    std::printf(
        "%d nodes checked (%d in contact, %d next to the kink): |R| = %.4e N, "
        "|R - grad E| = %.3e N\n",
        c->n_checked, c->n_in_contact, c->n_skipped, c->residual_N, c->difference_N);
  EXPECT_EQ(free.n_in_contact, 0);
  EXPECT_GT(pressed.n_in_contact, pressed.n_checked / 4);
  EXPECT_LT(pressed.n_in_contact, pressed.n_checked);
  // Both are central differences' truncation and round-off alone: measured 4.6e-10 of |R| out
  // of contact and 3.7e-10 in contact; 1e-8 allowed.
  EXPECT_LT(free.difference_N, 1e-8 * free.residual_N);
  EXPECT_LT(pressed.difference_N, 1e-8 * pressed.residual_N);
  // The analytic body's normal is its distance's gradient: no defect.
  EXPECT_EQ(backend.potential_defect_N(stretched.x), 0.0);
}

TEST(FemPotentialGradient, DiffersFromTheResidualByTheDefectOnAFacetedCylinder) {
  StretchedTube stretched;
  testing::TubeCase& tube = stretched.tube;
  // A 24-sided cylinder whose faces touch the tube's mean radius r at their middles (its
  // vertices at r / cos(7.5 deg), 0.26 mm further out): about half the nodes lie inside, and the
  // interpolated normal turns from the face's by up to 7.5 degrees round the axis (and tilts
  // along it, the end caps' normals blending into the rings').
  const double radius_m = 1.2 * tube.rest_radius_m / std::cos(7.5 * M_PI / 180.0);
  testing::write_obj(testing::temporary_path("fem_potential.obj"),
                     testing::revolution_surface({-0.1, 0.1}, {radius_m, radius_m}, 24));
  MeshBodyOptions options;
  options.import.up_axis = "+z";
  const auto body = load_mesh_body(testing::temporary_path("fem_potential.obj"), options);
  tube.problem.body = body.get();
  // Turned 4 degrees about the axis: the tube's vertices, 22.5 degrees apart from angle 0, then
  // keep 3.5 degrees or more from the prism's edges (every 15 degrees from 0), inside which the
  // distance to the faces has a kink, -min(d1, d2), that central differences would straddle.
  const Eigen::AngleAxisd turn(4.0 * M_PI / 180.0, Vec3::UnitZ());
  for (Vec3& p : stretched.x) p = turn * p;
  FemBackend backend(tube.problem, FemParameters{});
  backend.set_positions(stretched.x);
  const double h_m = 1e-7;
  const GradientCheck c = check_gradient(backend, *body, stretched.x, h_m);
  const double defect_N = backend.potential_defect_N(stretched.x);
  std::printf(
      "%d nodes checked (%d in contact, %d next to the kink): |R| = %.4e N, "
      "|R - grad E| = %.6e N, defect %.6e N\n",
      c.n_checked, c.n_in_contact, c.n_skipped, c.residual_N, c.difference_N, defect_N);
  ASSERT_GT(c.n_in_contact, 0);
  // The defect also counts the nodes next to the kink that the differences leave out: their
  // lambda = kA |g| < kA 10 h is below 1e-6 of the others' (kA g at g ~ 0.1 mm).
  // The defect is a fifth of R here, and it is the whole of R - grad E: they agree to 7 digits
  // (the differences' own error); 1e-6 allowed.
  EXPECT_GT(defect_N, 1e-3 * c.residual_N);
  EXPECT_NEAR(c.difference_N, defect_N, 1e-6 * defect_N);
}

}  // namespace
}  // namespace tightfit
