// The FE backend's Coulomb friction (contact/coulomb_friction.h through
// fem/contact_set_prediction.h and fem/membrane_assembly.h): its consistent tangent, the derivative
// of the return-mapped tangential force with the normal contact force it scales with, against
// central finite differences, on the sticking and the slipping branch, at random states; first one
// node at a time on three bodies, then the whole assembled Newton tangent of a tube that friction
// holds partly on a growing cylinder (docs/model.md, "Friction").
#include "bodies/cone.h"
#include "bodies/cylinder.h"
#include "bodies/mesh_body.h"
#include "central_difference.h"
#include "contact/penalty_contact.h"
#include "fem/contact_set_prediction.h"
#include "fem/fem_backend.h"
#include "residual_jacobian.h"
#include "tests/bodies/body_mesh_files.h"
#include "tube_problem.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>

namespace tightfit {
namespace {

// One node's normal contact and friction on its own branches (no step prediction), exact
// (unsymmetrised) tangent.
struct NodeModel {
  Vec3 force_N = Vec3::Zero();
  Mat3 stiffness_N_per_m = Mat3::Zero();
};

NodeModel node_model(const RigidBody& body, const ContactNodes& nodes, const Vec3& x) {
  NodeModel m;
  model_node_contact(body, nodes, 0, x, true, false, m.force_N, m.stiffness_N_per_m);
  return m;
}

struct RandomStateCounts {
  int sticking = 0, slipping = 0, skipped = 0;
  double largest_error = 0.0;  // |K - K_fd| / |K|
};

// Random states of one node pressed into `body` near `centre` (on the body's surface): the
// node up to 2 cm round and along from it and 10 um to 0.3 mm deep, its anchor up to 3 mm from
// its foot, the multiplier estimate 0 to 0.5 N, the normal penalty 2e3 N/m, mu 0.1 to 1 and
// k_t 1e2 to 1e4 N/m: the trial force k_t |u| from 0 to 30 N against mu N of 0.01 to 1.1 N, so
// both branches come up. A state within 100 central-difference steps of a kink (the cone's
// edge k_t |u| = mu N, or N = 0) is skipped: the difference would straddle it.
RandomStateCounts check_random_states(const RigidBody& body, const Vec3& centre, int n_states,
                                      unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0), sym(-1.0, 1.0);
  const double kA = 2e3;
  RandomStateCounts counts;
  for (int i = 0; i < n_states; ++i) {
    const Vec3 near = centre + 0.02 * Vec3(sym(random), sym(random), sym(random));
    const SurfacePoint foot = body.query(near);
    const Vec3 n = foot.outward_normal;
    // Moved along the normal rather than placed at its foot: a mesh body's feet gather on the
    // facets' edges, where its normal field is only continuous.
    const Vec3 x = near - (foot.signed_distance_m + 1e-5 + 2.9e-4 * unit(random)) * n;
    Vec3 slide(sym(random), sym(random), sym(random));
    slide -= n.dot(slide) * n;
    const Vec3 anchor_near = foot.closest_point_m + 3e-3 * unit(random) * slide.normalized();
    const double mu = 0.1 + 0.9 * unit(random);
    const double k_t = std::pow(10.0, 2.0 + 2.0 * unit(random));
    ContactNodes nodes;
    nodes.penalty_N_per_m = {kA};
    nodes.multiplier_N = {0.5 * unit(random)};
    nodes.friction = FrictionAnchors(mu, k_t / 1e-4, {1e-4});
    nodes.friction.place(body, {anchor_near});
    const SurfacePoint at_x = body.query(x);
    const double lambda = contact_multiplier_N(nodes.multiplier_N[0], kA, at_x.signed_distance_m);
    const double offset_m = nodes.friction.offset(0, body, x, at_x).u.norm();
    const double trial_N = k_t * offset_m;
    // The slip direction u / |u| turns over a length |u|: the step stays 1e-4 |u| below it
    // (truncation 1e-8 of the tangent), and 1e-7 m at most (round-off 1e-16 |f| / h).
    const double h = std::min(1e-7, 1e-4 * offset_m);
    // How far x is from each kink, in central-difference steps.
    const double kink_margin = 100.0 * h * (k_t + mu * kA);
    if (lambda < 100.0 * h * kA || std::abs(trial_N - mu * lambda) < kink_margin) {
      ++counts.skipped;
      continue;
    }
    const bool slipping = nodes.friction.response(0, body, x, at_x, lambda).slipping;
    EXPECT_EQ(slipping, trial_N > mu * lambda);
    (slipping ? counts.slipping : counts.sticking) += 1;
    const NodeModel m = node_model(body, nodes, x);
    const Mat3 K_fd = testing::minus_force_jacobian(
        [&](const Vec3& y) { return node_model(body, nodes, y).force_N; }, x, h);
    counts.largest_error = std::max(
        counts.largest_error, (m.stiffness_N_per_m - K_fd).norm() / m.stiffness_N_per_m.norm());
  }
  return counts;
}

// Measured largest |K - K_fd| / |K| over 400 states per body: 4.6e-9 (cylinder), 3.1e-8
// (cone), 1.0e-7 (mesh body, whose smooth normal field has the largest third derivatives).
// 1e-6 allowed: ten times the largest.
const double kNodeTolerance = 1e-6;

void expect_random_states_match(const char* name, const RigidBody& body, const Vec3& centre,
                                unsigned seed) {
  const RandomStateCounts c = check_random_states(body, centre, 400, seed);
  std::printf(
      "%s: %d sticking, %d slipping, %d near a kink skipped; largest |K - K_fd| / |K| "
      "%.2e\n",
      name, c.sticking, c.slipping, c.skipped, c.largest_error);
  // Both branches, each at least 30 times of the 400 (measured: 48 to 83 sticking, 303 to 325
  // slipping).
  EXPECT_GE(c.sticking, 30) << name;
  EXPECT_GE(c.slipping, 30) << name;
  EXPECT_LT(c.largest_error, kNodeTolerance) << name;
}

TEST(FemNodalFrictionTangent, RandomStatesStickingAndSlippingOnThreeBodies) {
  const Cylinder cylinder(Vec3(0.01, 0, 0), Vec3(1, 1, 3), 0.05);
  expect_random_states_match("cylinder", cylinder,
                             cylinder.surface_point_m(SurfaceLocation{-1, Vec3(0.02, 0.7, 0)}), 1);

  ConeOptions cone_options;
  cone_options.axis = Vec3(0.3, -0.2, 1.0);
  cone_options.half_angle_deg = 12.0;
  const Cone cone(cone_options);
  expect_random_states_match("cone", cone, cone.query(Vec3(0.06, 0.01, 0.02)).closest_point_m, 2);

  // A 16-sided surface of revolution whose radius changes along it (smooth normal field).
  testing::write_obj(testing::temporary_path("fem_friction.obj"),
                     testing::revolution_surface({-0.1, 0.0, 0.1}, {0.05, 0.055, 0.045}, 16));
  MeshBodyOptions o;
  o.import.up_axis = "+z";
  const auto body = load_mesh_body(testing::temporary_path("fem_friction.obj"), o);
  expect_random_states_match(
      "mesh body", *body,
      body->query(Vec3(0.06 * std::cos(0.2), 0.06 * std::sin(0.2), 0.02)).closest_point_m, 3);
}

// A tube "T" 6 cm high (two panels 15.7 cm wide, 2 cm x 1.5 cm edges, 80 vertices; linear Biot
// with the default fabric, free ends) on a cylinder grown from its rest radius to alpha 1.3 with
// mu = 0.3: the anchors the growing body carries outwards hold the tube in the
// middle while its ends slip (tests/cases/test_friction_on_cylinder.cc), so the converged state
// has nodes on both branches.
struct HeldTube {
  testing::TubeCase tube{"linear biot", EndCondition::free_ends,
                         make_tube_garment("T", 0.157, 0.06, 2, MeshSpacing{0.02, 0.015})};
  std::unique_ptr<FemBackend> backend;
  StepReport last;

  HeldTube() {
    tube.problem.friction_coefficient = 0.3;
    // The scenario's default: the tangential penalty ratio 1 times the normal penalty (here
    // that of cases/cylinder_45T.prm, 4.35e7 Pa/m).
    tube.problem.tangential_stiffness_Pa_per_m = 4.35e7;
    backend = std::make_unique<FemBackend>(tube.problem, FemParameters{});
    backend->set_positions(tube.placed(tube.rest_radius_m));
    for (int step = 0; step <= 3; ++step) {
      const double alpha = 1.0 + 0.1 * step;
      tube.grow_to(alpha);
      last = backend->solve({step, alpha, false});
    }
  }
};

// The nodes on each branch at `x` (degree 1: nodes are vertices), read from the residual alone:
// the contact force f_c = -R - f_internal splits into lambda n and the friction force, which is
// at the cone's edge |f_t| = mu lambda exactly when the node slips.
struct Branches {
  int sticking = 0, slipping = 0;
};
Branches branches_at(const HeldTube& held, const std::vector<Vec3>& x, const Eigen::VectorXd& R) {
  const std::vector<Vec3> internal = held.backend->internal_force_N(x);
  Branches b;
  for (std::size_t k = 0; k < x.size(); ++k) {
    const Vec3 f_c = -Vec3(R.segment<3>(3 * k)) - internal[k];
    const Vec3 n = held.tube.cylinder->query(x[k]).outward_normal;
    const double lambda = f_c.dot(n);
    if (lambda <= 0.0) continue;
    const double friction_N = (f_c - lambda * n).norm();
    (friction_N > 0.3 * lambda * (1 - 1e-9) ? b.slipping : b.sticking) += 1;
  }
  return b;
}

TEST(FemFrictionTangent, AssembledTangentMatchesFiniteDifferencesOnBothBranches) {
  const HeldTube held;
  ASSERT_GT(held.last.n_slipping, 0) << held.last.text();
  ASSERT_LT(held.last.n_slipping, held.last.n_in_contact) << held.last.text();
  std::printf("converged at alpha 1.3: %d of %d nodes in contact slipping\n", held.last.n_slipping,
              held.last.n_in_contact);
  const std::vector<Vec3> converged =
      held.backend->node_positions(held.backend->state().positions_m);
  std::mt19937 random(5);
  // Random moves of every node, 10 um and 50 um: the slipping nodes of the converged state lie
  // on the cone's edge (the return mapping puts them there), and the moves carry each to one
  // side of it, far enough that no difference straddles it; at 50 um most nodes slip and some
  // leave contact. The step is 1e-9 m: a slipping node's offset |u| = mu N / k_t is a few um
  // here, and its direction u / |u| turns over that length (a step of 1e-7 m read 7e-6 of the
  // tangent wrong on that truncation alone).
  for (const double amplitude_m : {1e-5, 5e-5}) {
    std::uniform_real_distribution<double> noise(-amplitude_m, amplitude_m);
    std::vector<Vec3> x = converged;
    for (Vec3& p : x) p += Vec3(noise(random), noise(random), noise(random));
    Eigen::VectorXd R;
    Eigen::MatrixXd K;
    held.backend->linearise(x, R, K);
    const Branches b = branches_at(held, x, R);
    const int n = static_cast<int>(R.size());
    const Eigen::MatrixXd K_fd = testing::residual_jacobian(*held.backend, x, 1e-9);
    const double error = (K - K_fd).norm() / K.norm();
    const double asymmetry = (K - K.transpose()).norm() / K.norm();
    std::printf(
        "moves of %.0e m: %d nodes, %d sticking, %d slipping; |K - K_fd| / |K| = %.2e, "
        "|K - K^T| / |K| = %.2e\n",
        amplitude_m, n / 3, b.sticking, b.slipping, error, asymmetry);
    EXPECT_GT(b.sticking, 0);
    EXPECT_GT(b.slipping, 0);
    // Measured 5.5e-9 (10 um: 15 sticking, 65 slipping) and 4.4e-9 (50 um: 2 sticking, 56
    // slipping, 22 out of contact); 1e-7 allowed, 18 times the larger.
    EXPECT_LT(error, 1e-7);
    // The slipping nodes' mu s (dlambda/dx)^T makes the tangent unsymmetric (measured 0.26 and
    // 0.36; the frictionless tangent on the analytic cylinder is symmetric to 1e-12).
    EXPECT_GT(asymmetry, 0.1);
  }
}

}  // namespace
}  // namespace tightfit
