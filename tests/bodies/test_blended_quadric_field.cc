// The blended quadric field (bodies/blended_quadric_field.h) on the MakeHuman female against a
// brute-force evaluation of its definition written out here: every vertex of the body, its
// Wendland weight and facing factor, its quadric, summed in plain loops.
#include "bodies/blended_quadric_field.h"
#include "bodies/mesh_body.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <string>

namespace tightfit {
namespace {

const std::string female =
    std::string(TIGHTFIT_BODIES_DIR) + "/makehuman_default_female_body_m.obj";

// phi and W at x by the definition (blended_quadric_field.h, eqs. F1 to F3): the facing
// normal m = v / |v|, v = sum_j w_j F_j n_j, F_j = S((n_j . m0 - cos 160) / (cos 140 - cos 160));
// then, for the vertices with F_i > 0, w_i = psi(|x - p_i| / s_i) S(2 (n_i . m + 1/2)), psi(r) = (1
// - r)^4 (4 r + 1) for r < 1, S the quintic smoothstep clamped to [0, 1], d_i = n_i . (x - p_i) +
// (x - p_i)^T K_i (x - p_i) / 2 + c_i, phi = sum w_i d_i / sum w_i.
struct BruteForce {
  double weight_sum = 0.0, phi_m = 0.0;
  int terms = 0;
};
double smoothstep(double u) {
  const double a = std::clamp(u, 0.0, 1.0);
  return a * a * a * (10 - 15 * a + 6 * a * a);
}
BruteForce brute_force(const BlendedQuadricField& field, const Vec3& x, const Vec3& m0) {
  const double cos140 = std::cos(140 * M_PI / 180), cos160 = std::cos(160 * M_PI / 180);
  const auto wendland = [&](int i) {
    const double r = (x - field.position(i)).norm() / field.support_m(i);
    return r < 1.0 ? std::pow(1 - r, 4) * (4 * r + 1) : 0.0;
  };
  Vec3 v = Vec3::Zero();
  for (int i = 0; i < field.vertex_count(); ++i)
    v += wendland(i) * smoothstep((field.normal(i).dot(m0) - cos160) / (cos140 - cos160)) *
         field.normal(i);
  BruteForce b;
  if (!(v.norm() > 0)) return b;
  const Vec3 m = v.normalized();
  double weighted = 0.0;
  for (int i = 0; i < field.vertex_count(); ++i) {
    const double screen = smoothstep((field.normal(i).dot(m0) - cos160) / (cos140 - cos160));
    const double w = wendland(i) * smoothstep(2.0 * (field.normal(i).dot(m) + 0.5));
    if (!(w > 0 && screen > 0)) continue;
    const Vec3 delta = x - field.position(i);
    const double d =
        field.normal(i).dot(delta) + 0.5 * delta.dot(field.curvature(i) * delta) + field.shift_m(i);
    b.weight_sum += w;
    weighted += w * d;
    ++b.terms;
  }
  if (b.weight_sum > 0) b.phi_m = weighted / b.weight_sum;
  return b;
}

// The female (faceted: the flat surface's answers the field is given) and her field, and
// random points near her surface: off a random vertex by up to `normal_m` along its normal
// and up to `sideways_m` in each coordinate.
struct FemaleField {
  std::unique_ptr<MeshBody> body = load_mesh_body(female, {});
  BlendedQuadricField field;
  std::mt19937 random;
  FemaleField(unsigned seed) : random(seed) {
    field.build(body->surface().vertices_m, body->surface().triangles, body->vertex_normals());
  }
  Vec3 point_near(double normal_m, double sideways_m) {
    std::uniform_int_distribution<int> vertex(0, int(body->surface().vertices_m.size()) - 1);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const int v = vertex(random);
    return body->surface().vertices_m[v] + normal_m * unit(random) * body->vertex_normals()[v] +
           sideways_m * Vec3(unit(random), unit(random), unit(random));
  }
};

// Points from 5 mm inside to 5 mm outside the surface over the whole body, off random vertices
// along their normals and sideways; the flat surface's closest triangle, normal and dn/dx as
// the mesh body gives them to the field.
TEST(BlendedQuadricField, EqualsTheBruteForceSumOverEveryVertex) {
  FemaleField female_field(31);
  const auto& body = female_field.body;
  const BlendedQuadricField& field = female_field.field;
  double largest_phi = 0.0, largest_weight = 0.0;
  int differing = 0, points = 0;
  for (int k = 0; k < 20000; ++k, ++points) {
    const Vec3 x = female_field.point_near(0.005, 0.005);
    const SurfacePoint flat = body->query(x);
    const BlendedQuadricField::Value got =
        field.evaluate(x, flat.outward_normal, flat.normal_derivative_per_m);
    const BruteForce want = brute_force(field, x, flat.outward_normal);
    const double dphi = std::abs(got.phi_m - want.phi_m),
                 dw = std::abs(got.weight_sum - want.weight_sum);
    if (dphi > 1e-12 || dw > 1e-12) {
      ++differing;
      if (dphi > 1e-4)
        std::printf("x %.5f %.5f %.5f: phi %.6g vs %.6g, W %.6g vs %.6g (%d terms)\n", x.x(), x.y(),
                    x.z(), got.phi_m, want.phi_m, got.weight_sum, want.weight_sum, want.terms);
    }
    largest_phi = std::max(largest_phi, dphi);
    largest_weight = std::max(largest_weight, dw);
  }
  std::printf("%d of %d points differ; largest differences: phi %.3g m, W %.3g\n", differing,
              points, largest_phi, largest_weight);
  EXPECT_LT(largest_phi, 1e-15);
  EXPECT_LT(largest_weight, 1e-14);
}

// A garment vertex's kept vertices (vertices_near round where it was, radius r): every point
// within r of there gets from them the value the grid's cell gives, to the last bit (the same
// quadrics, added in the same ascending order). Points up to 5 mm off the surface, r = 1 mm
// (about a tenth of the female's mean edge, as MeshBody keeps them), each moved up to r; and
// the list is shorter than a cell's (it is the point of keeping it).
TEST(BlendedQuadricField, KeptVerticesGiveTheGridsValueExactly) {
  FemaleField female_field(43);
  const auto& body = female_field.body;
  const BlendedQuadricField& field = female_field.field;
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double radius_m = 0.001;
  std::vector<int> kept;
  int differing = 0, points = 0, blended = 0;
  double kept_total = 0.0;
  for (int k = 0; k < 5000; ++k) {
    const Vec3 centre = female_field.point_near(0.005, 0.005);
    field.vertices_near(centre, radius_m, kept);
    kept_total += double(kept.size());
    ASSERT_TRUE(std::is_sorted(kept.begin(), kept.end()));
    for (int j = 0; j < 4; ++j, ++points) {
      Vec3 step(unit(female_field.random), unit(female_field.random), unit(female_field.random));
      if (step.norm() > 1.0) step /= step.norm();
      const Vec3 x = centre + radius_m * step;
      const SurfacePoint flat = body->query(x);
      const auto grid = field.evaluate(x, flat.outward_normal, flat.normal_derivative_per_m);
      const auto near = field.evaluate(x, flat.outward_normal, flat.normal_derivative_per_m, &kept);
      blended += grid.weight_sum > 0;
      differing += !(grid.phi_m == near.phi_m && grid.weight_sum == near.weight_sum &&
                     grid.gradient == near.gradient && grid.hessian_per_m == near.hessian_per_m);
    }
  }
  std::printf("%d of %d points differ (%d blended); %.1f vertices kept on average\n", differing,
              points, blended, kept_total / 5000);
  EXPECT_EQ(differing, 0);
  EXPECT_GT(blended, points / 2);  // most points lie where the field holds
}

// The shifts c_i that make the field vanish at the vertices, against the build's recurrence
// done again here from its definition: 30 Jacobi sweeps c_j <- c_j - phi(p_j), phi by the
// brute-force sum above (facing normal at p_j screened by n_j) over each vertex's neighbours
// found by a plain search over every vertex. The field builds them from its own candidate
// lists and a phi-only evaluation; the same sums, so equal up to the round-off of the two
// ways of writing them (measured 5.6e-17 m, shifts up to 3.5 cm); bound 1e-15 m. And the
// field's phi at the vertices (evaluate, with its derivatives) is the definition's with these
// shifts, what 30 sweeps leave of the misfit (up to 0.87 mm; the difference measured 2.0e-18 m,
// bound 1e-15 m).
TEST(BlendedQuadricField, ShiftsFollowTheJacobiSweepsOfTheDefinition) {
  FemaleField female_field(53);
  const BlendedQuadricField& field = female_field.field;
  const int n = field.vertex_count();
  std::vector<std::vector<int>> holding(n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      if ((field.position(j) - field.position(i)).norm() < field.support_m(i))
        holding[j].push_back(i);
  const double cos140 = std::cos(140 * M_PI / 180), cos160 = std::cos(160 * M_PI / 180);
  std::vector<double> shift(n, 0.0), misfit(n, 0.0);
  const auto phi_at = [&](int j) {
    const Vec3& x = field.position(j);
    const auto wendland = [&](int i) {
      const double r = (x - field.position(i)).norm() / field.support_m(i);
      return r < 1.0 ? std::pow(1 - r, 4) * (4 * r + 1) : 0.0;
    };
    const auto screen = [&](int i) {
      return smoothstep((field.normal(i).dot(field.normal(j)) - cos160) / (cos140 - cos160));
    };
    Vec3 v = Vec3::Zero();
    for (int i : holding[j]) v += wendland(i) * screen(i) * field.normal(i);
    const Vec3 m = v.normalized();
    double weight_sum = 0.0, weighted = 0.0;
    for (int i : holding[j]) {
      const double w = wendland(i) * smoothstep(2.0 * (field.normal(i).dot(m) + 0.5));
      if (!(w > 0 && screen(i) > 0)) continue;
      const Vec3 delta = x - field.position(i);
      weight_sum += w;
      weighted +=
          w * (field.normal(i).dot(delta) + 0.5 * delta.dot(field.curvature(i) * delta) + shift[i]);
    }
    return weighted / weight_sum;
  };
  for (int sweep = 0; sweep < BlendedQuadricField::interpolation_sweeps; ++sweep) {
    for (int j = 0; j < n; ++j) misfit[j] = phi_at(j);
    for (int j = 0; j < n; ++j) shift[j] -= misfit[j];
  }
  double worst_shift = 0.0, largest_shift = 0.0, worst_phi = 0.0, largest_phi = 0.0;
  for (int j = 0; j < n; ++j) {
    worst_shift = std::max(worst_shift, std::abs(field.shift_m(j) - shift[j]));
    largest_shift = std::max(largest_shift, std::abs(shift[j]));
    const double phi = field.evaluate(field.position(j), field.normal(j), Mat3::Zero()).phi_m;
    worst_phi = std::max(worst_phi, std::abs(phi - phi_at(j)));
    largest_phi = std::max(largest_phi, std::abs(phi));
  }
  std::printf(
      "shifts within %.3g m of the recurrence (largest %.3g m); phi at the vertices within %.3g m "
      "of the definition's (largest %.3g m)\n",
      worst_shift, largest_shift, worst_phi, largest_phi);
  EXPECT_LT(worst_shift, 1e-15);
  EXPECT_LT(worst_phi, 1e-15);
}

// The field's gradient against central differences of its phi, and its Hessian against central
// differences of its gradient, with the reference normal a linear function of x, m(x) = m0 +
// D (x - x0) (D the flat surface's dn/dx at x0), so that the facing factor's derivatives are
// exact (the facing normal m, eq. F2, is then C2 in x and its derivatives exact): over the whole
// body from 2 mm inside to 2 mm outside. The differences' error is their truncation,
// h^2 phi''' / 6: from h = 3e-8 to 1e-8 m it fell ninefold (gradient 9.7e-7 to 1.1e-7,
// Hessian 2.7e-2 to 3.0e-3 1/m), largest round the lips and eyes, where the supports are
// millimetres and the facing normal turns at up to 3.5e3 rad/m. Step 1e-8 m: bounds 3e-7
// (unit length) and 1e-2 1/m (entries up to hundreds per m). Round-off: 1e-17 m / 1e-8 m,
// below 1e-8. The points where some vertex's facing factor lies between 0 and 1 are counted,
// so that the factor's own derivatives (through the facing normal's, eq. F4) are exercised.
TEST(BlendedQuadricField, DerivativesMatchFiniteDifferences) {
  FemaleField female_field(37);
  const auto& body = female_field.body;
  const BlendedQuadricField& field = female_field.field;
  const double h = 1e-8;
  double worst_gradient = 0.0, worst_hessian = 0.0;
  int points = 0, turned = 0;
  for (int k = 0; k < 3000; ++k) {
    const Vec3 x0 = female_field.point_near(0.002, 0.004);
    const SurfacePoint flat = body->query(x0);
    const Vec3 m0 = flat.outward_normal;
    const Mat3 D = flat.normal_derivative_per_m;
    const auto at = [&](const Vec3& x) { return field.evaluate(x, Vec3(m0 + D * (x - x0)), D); };
    const BlendedQuadricField::Value f = at(x0);
    if (!(f.weight_sum > 0.05)) continue;  // where the body query uses the field at all
    ++points;
    bool partly_facing = false;
    for (int i = 0; i < field.vertex_count(); ++i) {
      const double a = 2.0 * (field.normal(i).dot(f.facing_normal) + 0.5);
      partly_facing |= (x0 - field.position(i)).norm() < field.support_m(i) && a > 0 && a < 1;
    }
    turned += partly_facing;
    for (int j = 0; j < 3; ++j) {
      const Vec3 e = Vec3::Unit(j);
      const BlendedQuadricField::Value plus = at(x0 + h * e), minus = at(x0 - h * e);
      worst_gradient =
          std::max(worst_gradient, std::abs((plus.phi_m - minus.phi_m) / (2 * h) - f.gradient[j]));
      worst_hessian = std::max(worst_hessian,
                               ((plus.gradient - minus.gradient) / (2 * h) - f.hessian_per_m.col(j))
                                   .cwiseAbs()
                                   .maxCoeff());
    }
  }
  std::printf(
      "%d points (%d with a vertex partly facing): gradient within %.3g, Hessian within "
      "%.4g 1/m\n",
      points, turned, worst_gradient, worst_hessian);
  EXPECT_GT(turned, 10);
  EXPECT_LT(worst_gradient, 3e-7);
  EXPECT_LT(worst_hessian, 1e-2);
}

}  // namespace
}  // namespace tightfit
