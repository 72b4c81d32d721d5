// Garment T on mesh bodies it was not tuned for, on both backends with default solver settings:
// a 256-sided mesh cylinder of radius 6 cm with an oblique axis (1, 2, 3), against the closed
// form (docs/closed-forms.md), and a mesh cylinder of elliptic section (semi-axes 6 and 4 cm),
// whose frictionless tube of uniform tension presses p = T kappa: the curvature's ratio
// between the ends of the major and of the minor axis, (a/b)^3 = 3.375.
#include "cases/cylinder_theory.h"
#include "tests/bodies/body_mesh_files.h"
#include "tests/cases/body_case.h"

#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>

namespace tightfit {
namespace {

using testing::run_body_case;
using testing::setting;

const double kRestRadius = 2 * 0.157 / (2 * M_PI);  // garment T: 4.997 cm

std::vector<std::string> garment_t() {
  return {"Garment/Name=T",
          "Garment/Tube/Panel width=0.157",
          "Garment/Tube/Panel height=0.24",
          "Garment/Edge length weft=0.008",
          "Garment/Edge length warp=0.022",
          "Material/Law=linear biot",
          "Protocol/Final alpha=1"};
}

// A closed cylinder of elliptic section, semi-axes a (along the section's first axis) and b,
// 256 vertices round, rings every centimetre over 50 cm (the smooth normal field then stays
// radial under the tube: tests/cases/test_tube_on_mesh_cylinder.cc), its axis along `axis`.
std::string elliptic_cylinder_obj(const std::string& name, double a_m, double b_m,
                                  const Vec3& axis) {
  std::vector<double> z, radius;
  for (int k = 0; k <= 50; ++k) z.push_back(-0.25 + 0.01 * k), radius.push_back(1.0);
  PolygonMesh mesh = testing::revolution_surface(z, radius, 256);
  const Eigen::Matrix3d turn =
      Eigen::Quaterniond::FromTwoVectors(Vec3::UnitZ(), axis.normalized()).toRotationMatrix();
  for (Vec3& v : mesh.vertices) v = turn * Vec3(a_m * v.x(), b_m * v.y(), v.z());
  const std::string path = testing::temporary_path(name);
  testing::write_obj(path, mesh);
  return path;
}

testing::BodyCaseRun tube_on(const std::string& obj, const Vec3& axis, const std::string& backend) {
  std::vector<std::string> settings = garment_t();
  for (const std::string& s : std::vector<std::string>{
           "Body/Kind=mesh", "Body/Mesh/File=" + obj, std::string("Body/Mesh/Up axis=+z"),
           std::string("Placement/Kind=tube round axis"),
           "Placement/Tube round axis/Axis=" + std::to_string(axis.x()) + "," +
               std::to_string(axis.y()) + "," + std::to_string(axis.z()),
           setting("Placement/Tube round axis/Radius", 0.0605)})
    settings.push_back(s);
  testing::BodyCaseRun r = run_body_case(settings, backend);
  EXPECT_TRUE(r.run.completed) << backend << ": " << r.run.failure << "\n" << r.log;
  return r;
}

// Measured (default settings): mass spring 450.10 Pa, FE 450.11 Pa against the closed form's
// 453.02 Pa, -0.65% both: the same shortfall as garment T's mesh on the analytic cylinder
// (docs/validation.md), the 256 facets' chord error (1 - cos(pi/256) = 7.5e-5, times 1/(alpha -
// 1) = 5: 3.8e-4 at most) adding little. Bound: 1% below, 0.1% above (the facets can only
// shorten the tube's path); the backends within 1e-4 of each other (measured 2e-5).
TEST(TubeOnObliqueMeshCylinder, MatchesClosedFormOnBothBackends) {
  const Vec3 axis(1, 2, 3);
  const double radius_m = 0.06;
  const std::string obj = elliptic_cylinder_obj("oblique_cylinder.obj", radius_m, radius_m, axis);
  const double closed_form =
      closed_form_pressure_Pa("linear biot", EndCondition::free_ends, FabricParameters{},
                              kRestRadius, radius_m / kRestRadius);
  double p[2] = {0, 0};
  int k = 0;
  for (const char* backend : {"massspring", "fem"}) {
    const testing::BodyCaseRun r = tube_on(obj, axis, backend);
    if (r.run.steps.empty()) return;
    p[k] = r.last().p_mean_Pa();
    std::printf("%s: %.3f Pa, closed form %.3f Pa (%+.3f%%), %d Newton/relaxation iterations\n",
                backend, p[k], closed_form, 100 * (p[k] / closed_form - 1),
                r.last().report.iterations);
    EXPECT_EQ(r.last().summary.contact_fraction, 1.0) << backend;
    EXPECT_GT(p[k] / closed_form - 1, -0.01) << backend;
    EXPECT_LT(p[k] / closed_form - 1, 0.001) << backend;
    ++k;
  }
  EXPECT_NEAR(p[1] / p[0], 1.0, 1e-4);
}

// The mean pressure of the vertices within `half_angle` of the section's axis `direction`
// (both ends), seen from the cylinder's axis x.
double end_pressure_Pa(const testing::BodyCaseRun& r, const Vec3& direction, double half_angle) {
  const std::vector<Vec3>& x = r.last().state.positions_m;
  const std::vector<double>& p = r.last().field.pressure_Pa;
  double sum = 0.0;
  int n = 0;
  for (std::size_t v = 0; v < x.size(); ++v) {
    const Vec3 across(0.0, x[v].y(), x[v].z());
    if (std::abs(across.normalized().dot(direction)) < std::cos(half_angle)) continue;
    sum += p[v];
    ++n;
  }
  return n > 0 ? sum / n : 0.0;
}

// p = T kappa with a uniform hoop tension T (frictionless, no axial load): the ratio of the
// pressures at the ends of the major (y, 6 cm) and minor (z, 4 cm) axes is (a/b)^3 = 3.375.
// Read as the mean over the vertices within 5 degrees of each axis (seen from the centre): the
// curvature falls off the major axis's end quickly, so the mean reads low; the exact
// curvature's mean over the same angular window is 3.337 times the
// minor end's (kappa(t) = a b / (b^2 sin^2 t + a^2 cos^2 t)^(3/2), t the parameter, a cos t
// along the major axis; computed below: 3.337). Measured: mass spring 3.367 (+0.9%) and FE 3.348
// (+0.3%); the mesh's error (the tube's 8 mm edges against the 2.7 cm radius of curvature at the
// major end, the pressure read per vertex) stated as 3%, 3.3 times the larger; the backends
// 0.56% apart, bound 1%.
TEST(TubeOnEllipticMeshCylinder, PressureFollowsCurvatureOnBothBackends) {
  const double a = 0.06, b = 0.04;
  const std::string obj = elliptic_cylinder_obj("elliptic_cylinder.obj", b, a, Vec3::UnitX());
  // The cylinder's section axes after the turn taking z to x: its first axis (b) and second (a).
  const Eigen::Matrix3d turn =
      Eigen::Quaterniond::FromTwoVectors(Vec3::UnitZ(), Vec3::UnitX()).toRotationMatrix();
  const Vec3 minor_direction = turn * Vec3::UnitX(), major_direction = turn * Vec3::UnitY();
  const double window = 5.0 * M_PI / 180.0;
  // The exact curvature's mean over the points within the window of each axis' end (by the
  // angle seen from the centre), sampled finely along the ellipse's parameter.
  auto curvature_mean = [&](const Vec3& direction) {
    double sum = 0.0;
    int n = 0;
    for (int i = 0; i < 100000; ++i) {
      const double t = 2 * M_PI * i / 100000.0;
      const double u = b * std::cos(t), w = a * std::sin(t);  // along minor, major directions
      const Vec3 point = u * minor_direction + w * major_direction;
      if (std::abs(point.normalized().dot(direction)) < std::cos(window)) continue;
      sum += a * b /
             std::pow(b * b * std::sin(t) * std::sin(t) + a * a * std::cos(t) * std::cos(t), 1.5);
      ++n;
    }
    return sum / n;
  };
  const double expected = curvature_mean(major_direction) / curvature_mean(minor_direction);
  double ratio[2] = {0, 0};
  int k = 0;
  for (const char* backend : {"massspring", "fem"}) {
    const testing::BodyCaseRun r = tube_on(obj, Vec3::UnitX(), backend);
    if (r.run.steps.empty()) return;
    ratio[k] =
        end_pressure_Pa(r, major_direction, window) / end_pressure_Pa(r, minor_direction, window);
    std::printf(
        "%s: major/minor end pressure %.4f, curvature's %.4f ((a/b)^3 = %.4f); mean %.3f Pa, %d "
        "Newton/relaxation iterations\n",
        backend, ratio[k], expected, std::pow(a / b, 3), r.last().p_mean_Pa(),
        r.last().report.iterations);
    EXPECT_NEAR(ratio[k] / expected, 1.0, 0.03) << backend;
    ++k;
  }
  EXPECT_NEAR(ratio[1] / ratio[0], 1.0, 0.01);
}

}  // namespace
}  // namespace tightfit
