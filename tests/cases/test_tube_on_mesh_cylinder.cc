// A tube on a mesh body: a faceted cylinder (a prism of n_round sides, written as an OBJ by the
// test) against the analytic cylinder of the same circumradius rho. Both runs put the same
// tube (garment T, linear Biot, nu = 0, free ends) at alpha = rho / R0 = 1.5 and compare mean
// contact pressures.
//
// The prediction from the polygon's sagitta s = rho (1 - cos(pi / n_round)): the faceted body's
// surface lies between rho - s (mid-face) and rho (edges) from the axis, so the tube wrapped on
// it is shorter than on the cylinder by a relative radius between s / (3 rho) (the polygon's
// own perimeter, 2 n rho sin(pi/n) = 2 pi rho (1 - (pi/n)^2 / 6)) and 2 s / (3 rho) (the
// surface's mean distance from the axis over angle, for a tube with fewer vertices round than
// the body has faces). For Eq. 7, p = Y (1 - 1/alpha) / R0, d ln p / d ln alpha = 1 / (alpha - 1),
// so the mesh reads low by between (1/3) and (2/3) of s / rho / (alpha - 1): never high, never
// more than s / rho / (alpha - 1). That is the faceted contact surface; the smooth one (the
// default, bodies/blended_quadric_field.h) lies within a few micrometres of the true cylinder
// (tests/contact/test_smooth_contact_surface.cc), so its tube reads the cylinder's pressure.
#include "tests/bodies/body_mesh_files.h"
#include "tests/cases/body_case.h"

#include <cmath>
#include <cstdio>

namespace tightfit {
namespace {

using testing::run_body_case;
using testing::setting;

const double kPanelWidth = 0.157;  // garment T: R0 = 2 x 0.157 / (2 pi) = 4.997 cm
const double kRestRadius = 2 * kPanelWidth / (2 * M_PI);
const double kAlpha = 1.5;
const int kFaces = 48;  // s / rho = 2.14e-3: the mesh reads low by 0.14% to 0.29% at alpha 1.5
// The smooth surface's tube against the cylinder's, relative: measured 6e-6 on both backends
// (kStopAtTheLoad below); bound 5e-5, a 7-fold margin and still 57 times below the faceted
// surface's shortfall (the smooth gap misses this cylinder by about 1 micrometre, 1.3e-5 of rho:
// tests/contact/test_smooth_contact_surface.cc measures 4.7 micrometres on a 24-sided one).
const double kSmoothBound = 5e-5;
// Every run stops at a tenth of the default rule at the contact load (core/load_step.h): at the
// default 1e-4 a settle may leave up to 1e-4 of the pressure, and the tube on the cylinder read
// 6.7e-5 above its smooth prism's on the mass-spring backend, the stop rule's noise, not the
// surface's. At 1e-5 the rule reads its floor here, a tenth of the tension-scale rule, about
// 2e-5 of the pressure; the faceted surface takes it too (its auto is 0).
const char* const kStopAtTheLoad = "Solver/Contact load tolerance=1e-5";

std::vector<std::string> tube_settings() {
  return {"Garment/Name=T",
          setting("Garment/Tube/Panel width", kPanelWidth),
          "Garment/Tube/Panel height=0.066",
          "Garment/Edge length weft=0.008",
          "Garment/Edge length warp=0.022",
          "Material/Law=linear biot",
          "Material/Poisson ratio weft-warp=0"};
}

double mean_pressure_Pa(const std::vector<std::string>& body, const std::string& backend) {
  std::vector<std::string> settings = tube_settings();
  settings.insert(settings.end(), body.begin(), body.end());
  const testing::BodyCaseRun r = run_body_case(settings, backend);
  EXPECT_TRUE(r.run.completed) << r.run.failure << "\n" << r.log;
  if (r.run.steps.empty()) return 0.0;
  EXPECT_EQ(r.last().summary.contact_fraction, 1.0);
  return r.last().p_mean_Pa();
}

// The kFaces-sided prism of circumradius rho_m, 30 cm long, written to a temporary OBJ named
// `name`; returns its path. Rings every 1 cm: the smooth normal field interpolates the vertex
// normals, and those of the rings at the caps lean towards the caps' normals; with one face
// from cap to cap the lean reached the tube (4% low, the contact force tilted along the axis).
// With the rings the vertex normals under the tube are radial and only the facets' chord error
// is left.
std::string write_prism(const std::string& name, double rho_m) {
  const std::string obj = testing::temporary_path(name);
  std::vector<double> z, radius;
  for (int k = 0; k <= 30; ++k) z.push_back(-0.15 + 0.01 * k), radius.push_back(rho_m);
  testing::write_obj(obj, testing::revolution_surface(z, radius, kFaces));
  return obj;
}

class TubeOnMeshCylinder : public ::testing::TestWithParam<const char*> {};

TEST_P(TubeOnMeshCylinder, MeanPressureWithinTheFacetsChordError) {
  const double rho = kAlpha * kRestRadius;
  const std::string obj = write_prism("mesh_cylinder.obj", rho);
  // The analytic cylinder starts a hair inside alpha 1.5 (its initial alpha must not exceed the
  // final one) and grows to 1.5 in a second step.
  const double p_cylinder = mean_pressure_Pa(
      {"Body/Kind=cylinder", "Body/Cylinder/Axis=0,0,1",
       setting("Body/Cylinder/Initial radius", rho * (1 - 1e-12)), "Protocol/Alpha increment=0.5",
       setting("Protocol/Final alpha", kAlpha), kStopAtTheLoad},
      GetParam());
  // Both surfaces settle as the cylinder does (the defaults elsewhere than on a faceted body
  // mesh, whose own, the rms at 3e-3, would loosen the stop rule beyond the facets' effect
  // measured here), and every contact round to the stop rule as an analytic body's rounds are
  // (Inexact contact rounds moved this tube's smooth mean by 6.8e-5, within the stop rule but
  // beyond the effect measured here): only the surface differs.
  auto on_prism = [&](const std::string& surface) {
    return mean_pressure_Pa(
        {"Body/Kind=mesh", "Body/Mesh/File=" + obj, "Body/Mesh/Up axis=+z",
         "Body/Mesh/Contact surface=" + surface, "Placement/Kind=tube round axis",
         "Placement/Tube round axis/Axis=0,0,1",
         setting("Placement/Tube round axis/Radius", 1.005 * rho), "Protocol/Final alpha=1",
         "Solver/Relative tolerance=1e-4", "Solver/Stop norm=largest", "Solver/Gap tolerance=1e-8",
         "Mass spring/Contact normal damping ratio=0", "Mass spring/Time step update frames=0",
         "Mass spring/Net force tolerance=0", "Mass spring/Inexact contact rounds=0",
         kStopAtTheLoad},
        GetParam());
  };
  const double p_faceted = on_prism("faceted"), p_smooth = on_prism("smooth");
  const double sagitta_ratio = 1 - std::cos(M_PI / kFaces);
  const double predicted_max = sagitta_ratio / (kAlpha - 1);
  const double shortfall = (p_cylinder - p_faceted) / p_cylinder;
  const double smooth_shortfall = (p_cylinder - p_smooth) / p_cylinder;
  std::printf(
      "%s: cylinder %.3f Pa, %d-sided prism %.3f Pa faceted, %.3f Pa smooth; shortfall "
      "%.4f%% faceted (predicted %.4f%% to %.4f%%), %.4f%% smooth\n",
      GetParam(), p_cylinder, kFaces, p_faceted, p_smooth, 100 * shortfall, 100 * predicted_max / 3,
      100 * 2 * predicted_max / 3, 100 * smooth_shortfall);
  EXPECT_GT(shortfall, 0.0);
  EXPECT_LT(shortfall, predicted_max);
  EXPECT_LT(std::abs(smooth_shortfall), kSmoothBound);
}

INSTANTIATE_TEST_SUITE_P(Backends, TubeOnMeshCylinder, ::testing::Values("massspring", "fem"));

TEST(TubeOnMeshCylinderImplicit, HeldTubeReachesRk4sPressureByTheImplicitRoute) {
  // The mass-spring implicit route on a mesh body (RK4's approach, Newton's rounds, RK4 after a
  // stall: docs/backends.md, "On a mesh body") with the held turn (every vertex held along the
  // axis): the smooth 48-sided prism of the test above, the same tube, the stop rule of the
  // analytic bodies (largest residual, 1e-4 of the tension scale), both integrators at their
  // defaults otherwise.
  const double rho = kAlpha * kRestRadius;
  const std::string obj = write_prism("mesh_cylinder_implicit.obj", rho);
  auto held = [&](const std::string& integrator) {
    return mean_pressure_Pa(
        {"Body/Kind=mesh", "Body/Mesh/File=" + obj, "Body/Mesh/Up axis=+z",
         "Placement/Kind=tube round axis", "Placement/Tube round axis/Axis=0,0,1",
         setting("Placement/Tube round axis/Radius", 1.005 * rho), "Protocol/Final alpha=1",
         "Constraints/Held groups=all", "Constraints/Held direction=0,0,1",
         "Solver/Relative tolerance=1e-4", "Solver/Stop norm=largest", "Solver/Gap tolerance=1e-8",
         "Mass spring/Integrator=" + integrator},
        "massspring");
  };
  const double p_rk4 = held("rk4"), p_implicit = held("implicit");
  // The same equilibrium within the stop rule's bound: it leaves each state within 1.4e-4 of
  // the contact force (test_cylinder_pressure.cc), so the two within 2.8e-4; measured 1.03e-4.
  EXPECT_NEAR(p_implicit / p_rk4, 1.0, 2.8e-4);
}

// What the tops have, on a small body case: the faceted 48-sided prism standing upright, the
// tube free (no held direction) under its weight, held by friction (0.3), every settle entry at
// the faceted body's defaults (the rms stop rule and the net-force limit), from the tube's
// placement; `entries` adds the backend's own.
testing::BodyCaseRun friction_held_tube_under_gravity(const std::string& obj_name,
                                                      const std::string& backend,
                                                      const std::vector<std::string>& entries) {
  const double rho = kAlpha * kRestRadius;
  const std::string obj = write_prism(obj_name, rho);
  std::vector<std::string> settings = tube_settings();
  for (const std::string& entry : std::vector<std::string>{
           "Body/Kind=mesh", "Body/Mesh/File=" + obj, std::string("Body/Mesh/Up axis=+z"),
           std::string("Body/Mesh/Contact surface=faceted"),
           std::string("Placement/Kind=tube round axis"),
           std::string("Placement/Tube round axis/Axis=0,0,1"),
           setting("Placement/Tube round axis/Radius", 1.005 * rho),
           std::string("Protocol/Final alpha=1"),
           std::string("Protocol/Gravity while settling=true"),
           std::string("Contact/Friction coefficient=0.3")})
    settings.push_back(entry);
  settings.insert(settings.end(), entries.begin(), entries.end());
  return run_body_case(settings, backend);
}

TEST(TubeOnMeshCylinderImplicit, FrictionHeldTubeUnderGravitySettlesByNewtonAlone) {
  // The implicit route runs Newton alone here (no RK4 approach with friction) on the projected
  // tangent (docs/backends.md, "The implicit route on the tops").
  auto hung = [&](const std::string& integrator) {
    return friction_held_tube_under_gravity("mesh_cylinder_friction_implicit.obj", "massspring",
                                            {"Mass spring/Integrator=" + integrator});
  };
  const testing::BodyCaseRun rk4 = hung("rk4"), implicit = hung("implicit");
  ASSERT_TRUE(rk4.run.completed) << rk4.run.failure << "\n" << rk4.log;
  ASSERT_TRUE(implicit.run.completed) << implicit.run.failure << "\n" << implicit.log;
  const double p_rk4 = rk4.last().p_mean_Pa(), p_implicit = implicit.last().p_mean_Pa();
  // Both meet the rms rule at 3e-3 of the tension scale, which bounds each mean pressure's
  // error by about that fraction; measured 1.3e-3 apart (864.38 Pa after 29 RK4 frames, 863.22
  // Pa after 7 Newton iterations); bound 3e-3, the rule's own size.
  EXPECT_NEAR(p_implicit / p_rk4, 1.0, 3e-3) << "rk4 " << p_rk4 << " Pa, implicit " << p_implicit;
}

TEST(TubeOnMeshCylinderFe, FrictionHeldTubeUnderGravitySettlesByPseudoTime) {
  // The same tube on the FE backend, its load step opened by pseudo time steps
  // (fem/pseudo_transient.h) that Newton's contact rounds end, to the shared stop rule alone (as
  // the tops' cases set: Residual tolerance = 0), every other Finite elements entry at its
  // default. Against the mass-spring backend's RK4 settle of the same case.
  const testing::BodyCaseRun rk4 =
      friction_held_tube_under_gravity("mesh_cylinder_friction_rk4.obj", "massspring", {});
  const testing::BodyCaseRun fe = friction_held_tube_under_gravity(
      "mesh_cylinder_friction_fe.obj", "fem",
      {"Finite elements/Pseudo time steps=2000", "Finite elements/Residual tolerance=0"});
  ASSERT_TRUE(rk4.run.completed) << rk4.run.failure << "\n" << rk4.log;
  ASSERT_TRUE(fe.run.completed) << fe.run.failure << "\n" << fe.log;
  const double p_rk4 = rk4.last().p_mean_Pa(), p_fe = fe.last().p_mean_Pa();
  std::printf("friction-held tube: rk4 %.3f Pa, fem %.3f Pa (%+.2e)\n%s\n", p_rk4, p_fe,
              p_fe / p_rk4 - 1, fe.last().report.text().c_str());
  // Both meet the rms rule at 3e-3 of the tension scale, which bounds each mean pressure's error
  // by about that fraction; measured 5.7e-4 apart (864.376 Pa after RK4, 863.887 Pa after 12
  // pseudo time steps and 1 Newton iteration); bound 3e-3, the rule's own size.
  EXPECT_NEAR(p_fe / p_rk4, 1.0, 3e-3) << "rk4 " << p_rk4 << " Pa, fem " << p_fe;
}

}  // namespace
}  // namespace tightfit
