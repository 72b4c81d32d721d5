// The dressing stage (massspring/dressing.h, Placement/Kind = dressing; docs/dressing.md).
// Two half-tube panels of the paper's "4 5T", unsewn on a circle round a cylinder shrunk to 0.7
// of its radius, sewn by the seam springs while the cylinder grows back: once welded, the load
// steps give the pressure of the tube started sewn (the same equilibrium) and the closed form
// p = T / r (docs/model.md, "Closed forms"). A garment far too small for its body cannot close
// its seams: the dressing fails naming the seam, the gap and where.
#include "bodies/cylinder.h"
#include "bodies/scaled_body.h"
#include "body_case.h"
#include "cases/case_parameters.h"
#include "cases/scenario.h"
#include "cases/scenario_run.h"
#include "cylinder_start.h"
#include "io/triangle_vtu_reader.h"
#include "massspring/seam_springs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace tightfit {
namespace {

const std::string source_dir = TIGHTFIT_SOURCE_DIR;
const double rest_radius_45T_m = 2 * 0.1878 / (2 * M_PI);

// cylinder_45T.prm (axis x through the origin, panels 24 cm along it) with the dressing start:
// each panel's middle on a circle of `circle_m` (front at angle 0 along -y, back at 180 degrees),
// the cylinder shrunk to 0.7 about its axis.
void dressing_case(CaseFile& file, double circle_m, const std::vector<std::string>& more = {}) {
  file.read(source_dir + "/cases/cylinder_45T.prm", {"Output/Write VTU=false"});
  file.set("Placement/Kind=dressing");
  file.set("Placement/Dressing/Centre=0,0,0");
  file.set("Placement/Dressing/Axis=1,0,0");
  file.set("Placement/Dressing/Front=0,-1,0");
  file.set(testing::setting("Placement/Dressing/Semi-axis side", circle_m));
  file.set(testing::setting("Placement/Dressing/Semi-axis front", circle_m));
  file.set("Placement/Dressing/Hem height=-0.12");
  file.set("Placement/Dressing/Growth frames=600");
  file.set("Placement/Dressing/Seam ramp frames=200");
  for (const std::string& m : more) file.set(m);
}

TEST(Dressing, SeamSpringForcesSumToZeroAndAreTheEnergysGradient) {
  // Zero-rest-length springs, energy k |x_a - x_b|^2 / 2 per pair: random positions, forces
  // against central differences of the energy, and their sum zero (Newton's third law).
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-0.1, 0.1);
  std::vector<Vec3> x(6);
  for (Vec3& p : x) p = Vec3(coordinate(random), coordinate(random), coordinate(random));
  const std::vector<std::pair<int, int>> pairs{{0, 1}, {2, 3}, {4, 5}, {1, 2}};
  const double k = 2600.0;
  const SeamSprings springs(pairs, k);
  std::vector<Vec3> f(x.size(), Vec3::Zero());
  springs.add_forces(x, f);
  Vec3 total = Vec3::Zero();
  for (const Vec3& fi : f) total += fi;
  const double scale = k * 0.1;  // N: a spring stretched by a tenth of a metre
  EXPECT_LT(total.norm(), 1e-13 * scale);
  const auto energy = [&](const std::vector<Vec3>& y) {
    double e = 0.0;
    for (const auto& [a, b] : pairs) e += 0.5 * k * (y[a] - y[b]).squaredNorm();
    return e;
  };
  const double h = 1e-6;
  for (std::size_t i = 0; i < x.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      std::vector<Vec3> plus = x, minus = x;
      plus[i][c] += h;
      minus[i][c] -= h;
      const double numeric = -(energy(plus) - energy(minus)) / (2 * h);
      // The energy is quadratic: central differences are exact up to round-off (~1e-9 N).
      EXPECT_NEAR(f[i][c], numeric, 1e-7 * scale) << "vertex " << i << " component " << c;
    }
}

TEST(Dressing, ScaledCylinderIsTheSmallerCylinder) {
  // A cylinder of radius 5 cm scaled by 0.7 about its axis is the cylinder of 3.5 cm, and about
  // a point on its axis too (its length is not seen): distances and normals agree.
  const Cylinder cylinder(Vec3::Zero(), Vec3::UnitX(), 0.05);
  const Cylinder smaller(Vec3::Zero(), Vec3::UnitX(), 0.035);
  ScaledBody about_axis(cylinder, Vec3::Zero(), Vec3::UnitX());
  ScaledBody about_point(cylinder, Vec3::Zero());
  about_axis.set_scale(0.7);
  about_point.set_scale(0.7);
  for (const Vec3& x : {Vec3(0.3, 0.02, 0.01), Vec3(-0.1, 0.0, 0.08), Vec3(0.0, -0.2, 0.1)}) {
    const SurfacePoint expected = smaller.query(x);
    for (const ScaledBody* body : {&about_axis, &about_point}) {
      const SurfacePoint s = body->query(x);
      EXPECT_NEAR(s.signed_distance_m, expected.signed_distance_m, 1e-15);
      EXPECT_LT((s.outward_normal - expected.outward_normal).norm(), 1e-14);
    }
  }
}

TEST(Dressing, TwoHalfTubesSewnRoundTheCylinderPressLikeTheSewnTube) {
  const std::vector<double> alphas = {1.2};
  std::ostringstream sewn_log, dressed_log;
  CaseFile sewn;
  sewn.read(source_dir + "/cases/cylinder_45T.prm", {"Output/Write VTU=false"});
  const RunResult tube =
      testing::run_on_cylinder(sewn, "massspring", alphas, rest_radius_45T_m, sewn_log);
  // The cylinder at alpha 1.2 (7.17 cm), shrunk to 5.02 cm; the panels start 2 cm outside it.
  CaseFile dressed_file;
  dressing_case(dressed_file, 0.07);
  const RunResult dressed =
      testing::run_on_cylinder(dressed_file, "massspring", alphas, rest_radius_45T_m, dressed_log);
  ASSERT_TRUE(tube.completed) << tube.failure;
  ASSERT_TRUE(dressed.completed) << dressed.failure << dressed_log.str();
  const StepMeasurement& a = tube.steps.back();
  const StepMeasurement& b = dressed.steps.back();
  std::printf("alpha 1.2: sewn start %.6f Pa, dressed %.6f Pa, theory %.6f Pa\n", a.p_mean_Pa(),
              b.p_mean_Pa(), a.p_theory_Pa);
  // Both settle to the same equilibrium within the stop rule (Relative tolerance 1e-4 of the
  // tension scale): measured 375.840208 against 375.840534 Pa, 8.7e-7 apart; 1e-5 allowed.
  EXPECT_NEAR(b.p_mean_Pa(), a.p_mean_Pa(), 1e-5 * a.p_mean_Pa());
  // The closed form p = T / r: the sewn tube meets it to 1 % at alpha 1.2 (docs/validation.md);
  // the dressed one must too.
  EXPECT_NEAR(b.p_mean_Pa(), b.p_theory_Pa, 1e-2 * b.p_theory_Pa);
  EXPECT_EQ(b.summary.contact_fraction, 1.0);
}

TEST(Dressing, DressedTubeWornWithGravityAndFrictionCarriesItsWeight) {
  // The top cases' settle (cases/top_female.prm): gravity on and Coulomb friction 0.3 between
  // the garment and the body. At the stable state the body's forces on the garment (normal and
  // friction) carry its weight and nothing else: their sum is m g upwards, m the fabric's
  // areal density times the two panels' rest area (2 x 18.78 x 24 cm, 9.528 g, 0.09347 N).
  const std::vector<double> alphas = {1.2};
  std::ostringstream log;
  CaseFile file;
  dressing_case(file, 0.07,
                {"Protocol/Gravity while settling=true", "Contact/Friction coefficient=0.3"});
  const RunResult dressed =
      testing::run_on_cylinder(file, "massspring", alphas, rest_radius_45T_m, log);
  ASSERT_TRUE(dressed.completed) << dressed.failure << log.str();
  const StepMeasurement& m = dressed.steps.back();
  const FabricParameters& fabric = file.parameters().fabric;
  const double weight_N = fabric.areal_density_kg_per_m2 * 2 * 0.1878 * 0.24 * 9.81;
  Vec3 carried_N = Vec3::Zero();
  for (const Vec3& f : m.state.contact_force_N) carried_N += f;
  std::printf("weight %.6f N, carried (%.3g, %.3g, %.6f) N\n", weight_N, carried_N.x(),
              carried_N.y(), carried_N.z());
  // The internal forces cancel, so the carried force is the weight less the residuals' sum,
  // each residual below the stop rule: measured 0.093469 N upwards (3e-5 of the weight short)
  // and 6e-13 N across; 1e-3 of the weight allowed either way.
  EXPECT_NEAR(carried_N.z(), weight_N, 1e-3 * weight_N);
  EXPECT_NEAR(carried_N.x(), 0.0, 1e-3 * weight_N);
  EXPECT_NEAR(carried_N.y(), 0.0, 1e-3 * weight_N);
}

// The tube round the cylinder at alpha 3, whose seams cannot close (below), in 1500 frames.
CaseParameters too_small_for_the_body() {
  CaseFile file;
  dressing_case(file, 0.14, {"Placement/Dressing/Maximum frames=1500", "Protocol/Final alpha=3.5"});
  testing::start_cylinder_at(file, 3.0, rest_radius_45T_m);
  return file.parameters();
}

TEST(Dressing, AGarmentTooSmallForTheBodyFailsNamingTheSeam) {
  // The cylinder at alpha 3 (18 cm): round it the tube stretches by 200 %, where a seam spring
  // of 20 x the stiffness scale balances the hoop tension at a gap of about 2 / 20 of a vertex's
  // seam length, twice the closing gap (0.05 of an edge): the seams cannot close.
  CaseParameters parameters = too_small_for_the_body();
  parameters.output.write_files = false;
  try {
    make_scenario(parameters);
    FAIL() << "the dressing closed a seam it cannot";
  } catch (const SolverError& e) {
    const std::string message = e.what();
    std::printf("%s\n", message.c_str());
    EXPECT_NE(message.find("did not close within 1500 frames"), std::string::npos) << message;
    EXPECT_NE(message.find("on seam 4 5T"), std::string::npos) << message;
    EXPECT_NE(message.find("widest seam gap"), std::string::npos) << message;
  }
}

TEST(Dressing, AFailedDressingWritesTheStateItStoppedIn) {
  // The garment too small for its body above, with files written: the error names the two VTU
  // files and the body's scale s it stopped at (1 once the growth frames are over; below 1
  // where the body waits for the seams, as a pattern arrangement's does); the body in the second is
  // the cylinder at that scale, every point at most s alpha R0 from the axis and the farthest at it
  // (the cylinder's own points, so to the six digits the message prints: 1e-5 relative); the panels
  // in the first lie pressed on that cylinder, none more than 1 mm inside it (the penalty's depth p
  // / k).
  CaseParameters parameters = too_small_for_the_body();
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "tightfit_test_failed_dressing";
  std::filesystem::remove_all(dir);
  parameters.output.directory = dir.string();
  parameters.output.write_files = true;
  double scale = 0.0;
  try {
    make_scenario(parameters);
    FAIL() << "the dressing closed a seam it cannot";
  } catch (const SolverError& e) {
    const std::string message = e.what();
    const std::size_t at = message.find("(body scale ");
    ASSERT_NE(at, std::string::npos) << message;
    scale = std::stod(message.substr(at + 12));
    EXPECT_NE(message.find((dir / "dressing_failed.vtu").string()), std::string::npos) << message;
    EXPECT_NE(message.find((dir / "dressing_failed_body.vtu").string()), std::string::npos)
        << message;
  }
  const TriangleGrid body = read_triangle_vtu((dir / "dressing_failed_body.vtu").string());
  ASSERT_GT(scale, 0.0);
  const double radius_m = scale * 3.0 * rest_radius_45T_m;
  double farthest_m = 0.0;
  for (const Vec3& p : body.points_m) {
    const double r = std::hypot(p.y(), p.z());
    EXPECT_LE(r, radius_m * (1 + 1e-5));
    farthest_m = std::max(farthest_m, r);
  }
  EXPECT_NEAR(farthest_m, radius_m, 1e-5 * radius_m);
  const TriangleGrid garment = read_triangle_vtu((dir / "dressing_failed.vtu").string());
  ASSERT_FALSE(garment.triangles.empty());
  double nearest_m = 1.0;
  for (const Vec3& p : garment.points_m) nearest_m = std::min(nearest_m, std::hypot(p.y(), p.z()));
  std::printf("garment points from %.6f m of the axis, the body's radius %.6f m\n", nearest_m,
              radius_m);
  EXPECT_GE(nearest_m, radius_m - 1e-3);
  std::filesystem::remove_all(dir);
}

TEST(Dressing, PanelsPlacedInsideTheShrunkBodyArePushedOutAndSewn) {
  // The cylinder at alpha 1.2 (7.17 cm) shrunk to 0.9 (6.45 cm) and the panels on a 6 cm circle:
  // every vertex starts 4.5 mm inside it, far less than half the garment's size (the square
  // root of its rest area, 0.30 m): each is pushed out along the cylinder's normal by its depth
  // (plus a tenth of an edge) and the dressing goes on. Sewn, the tube lies on the whole
  // cylinder: the welded vertices are put back onto its surface (measured at its radius to
  // 1e-6 m); 0.1 mm allowed either side.
  CaseFile file;
  dressing_case(file, 0.06, {"Placement/Dressing/Start scale=0.9"});
  testing::start_cylinder_at(file, 1.2, rest_radius_45T_m);
  CaseParameters parameters = file.parameters();
  parameters.output.write_files = false;
  const std::unique_ptr<Scenario> scenario = make_scenario(parameters);
  const double r_m = 1.2 * rest_radius_45T_m;
  double smallest = 1e9, largest = 0.0;
  for (const Vec3& x : scenario->start_positions_m) {
    const double radius = std::hypot(x.y(), x.z());
    smallest = std::min(smallest, radius);
    largest = std::max(largest, radius);
  }
  std::printf("sewn after the push-out: radius %.6f to %.6f m (cylinder %.6f m)\n", smallest,
              largest, r_m);
  EXPECT_GT(smallest, r_m - 1e-4);
  EXPECT_LT(largest, r_m + 1e-4);
}

TEST(Dressing, PanelsPlacedDeepInsideTheShrunkBodyAreRefusedNamingTheVertex) {
  // The cylinder at alpha 4 (23.9 cm) shrunk to 0.9 (21.5 cm) and the panels on a 4 cm circle:
  // every vertex starts 17.5 cm inside it, deeper than half the garment's size (0.15 m): no near
  // miss but a placement on the wrong side of the body, refused naming the vertex.
  CaseFile file;
  dressing_case(file, 0.04, {"Placement/Dressing/Start scale=0.9", "Protocol/Final alpha=4"});
  testing::start_cylinder_at(file, 4.0, rest_radius_45T_m);
  CaseParameters parameters = file.parameters();
  try {
    make_scenario(parameters);
    FAIL() << "a start deep inside the body was accepted";
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("Placement/Dressing: dressing: panel 4 5T panel 1 vertex 0 starts"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("inside the body shrunk to 0.9"), std::string::npos) << message;
    EXPECT_NE(message.find("more than half the garment's size"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace tightfit
