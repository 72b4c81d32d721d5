// The "Mass spring" subsection: every entry declared with its range, parsed into the settings.
#include "massspring/massspring_parameters.h"

#include <deal.II/base/parameter_handler.h>

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace tightfit {
namespace {

TEST(MassSpringParameters, DefaultsParseToTheStructsDefaults) {
  dealii::ParameterHandler prm;
  MassSpringParameters::declare_parameters(prm);
  MassSpringParameters parsed;
  parsed.quasi_static_frames = 7;  // must be overwritten by the declared default
  parsed.parse_parameters(prm);
  const MassSpringParameters defaults;
  EXPECT_EQ(parsed.time_step_s, defaults.time_step_s);
  EXPECT_EQ(parsed.quasi_static_frames, defaults.quasi_static_frames);
  EXPECT_EQ(parsed.maximum_frames, defaults.maximum_frames);
  EXPECT_EQ(parsed.bending_rigidity_N_m, defaults.bending_rigidity_N_m);
  EXPECT_EQ(parsed.damping_per_s, defaults.damping_per_s);
  EXPECT_EQ(parsed.placement, Placement::sewn_tube);
  EXPECT_EQ(parsed.placement_gap_m, defaults.placement_gap_m);
  EXPECT_EQ(parsed.seam_stiffness_factor, defaults.seam_stiffness_factor);
}

TEST(MassSpringParameters, ReadsTheFlatPanelPlacement) {
  dealii::ParameterHandler prm;
  MassSpringParameters::declare_parameters(prm);
  prm.parse_input_from_string(
      "subsection Mass spring\n  set Placement = flat panels\n  set Placement gap = 0.01\n"
      "  set Seam spring stiffness factor = 40\nend\n");
  MassSpringParameters p;
  p.parse_parameters(prm);
  EXPECT_EQ(p.placement, Placement::flat_panels);
  EXPECT_DOUBLE_EQ(p.placement_gap_m, 0.01);
  EXPECT_DOUBLE_EQ(p.seam_stiffness_factor, 40.0);
  EXPECT_ANY_THROW(
      prm.parse_input_from_string("subsection Mass spring\n  set Placement = draped\nend\n"));
  p.seam_stiffness_factor = 0.0;
  EXPECT_THROW(p.validate(), std::invalid_argument);
}

TEST(MassSpringParameters, ReadsAFileAndRejectsValuesOutOfRange) {
  dealii::ParameterHandler prm;
  MassSpringParameters::declare_parameters(prm);
  prm.parse_input_from_string(
      "subsection Mass spring\n  set Time step = 2e-5\n  set Bending rigidity = 5e-6\n"
      "  set Maximum frames = 1000\nend\n");
  MassSpringParameters p;
  p.parse_parameters(prm);
  EXPECT_DOUBLE_EQ(p.time_step_s, 2e-5);
  EXPECT_DOUBLE_EQ(p.bending_rigidity_N_m, 5e-6);
  EXPECT_EQ(p.maximum_frames, 1000);
  EXPECT_ANY_THROW(
      prm.parse_input_from_string("subsection Mass spring\n  set Damping = -1\nend\n"));
  // The stop rule is the Solver subsection's (core/load_step.h): out of range there.
  p.stop.relative_tolerance = 2;
  EXPECT_THROW(p.validate(), std::invalid_argument);
  p.stop.relative_tolerance = 0;  // the FE backend's own rule; not one the mass springs have
  EXPECT_THROW(p.validate(), std::invalid_argument);
}

// `p` refused by validate() with a message naming Mass spring/`entry`.
void expect_refused_naming(const MassSpringParameters& p, const std::string& entry) {
  try {
    p.validate();
    ADD_FAILURE() << "Mass spring/" << entry << " was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("Mass spring/" + entry), std::string::npos) << e.what();
  }
}

// The entry read from a file at `value`, and a file giving it `out_of_range` refused (by the
// file's pattern or, for an entry that may be auto, when read).
MassSpringParameters read_with(const std::string& entry, const std::string& value,
                               const std::string& out_of_range) {
  dealii::ParameterHandler prm;
  MassSpringParameters::declare_parameters(prm);
  const std::string head = "subsection Mass spring\n  set " + entry + " = ";
  prm.parse_input_from_string(head + value + "\nend\n");
  MassSpringParameters p;
  p.parse_parameters(prm);
  EXPECT_ANY_THROW({
    prm.parse_input_from_string(head + out_of_range + "\nend\n");
    MassSpringParameters refused;
    refused.parse_parameters(prm);
  });
  return p;
}

// The entries left at auto: the struct's defaults on an analytic body or a frictionless smooth
// mesh, the rough mesh body's (on_rough_mesh_body: faceted, or friction); a number given wins on
// either; a word that is neither is refused naming the entry.
TEST(MassSpringParameters, AutoEntriesTakeTheRoughMeshBodysDefaultsOnlyThere) {
  dealii::ParameterHandler prm;
  MassSpringParameters::declare_parameters(prm);
  MassSpringParameters elsewhere;
  elsewhere.parse_parameters(prm, false);
  const MassSpringParameters d;
  EXPECT_EQ(elsewhere.contact_normal_damping_ratio, d.contact_normal_damping_ratio);
  EXPECT_EQ(elsewhere.time_step_update_frames, d.time_step_update_frames);
  EXPECT_EQ(elsewhere.net_force_tolerance, d.net_force_tolerance);
  MassSpringParameters faceted;
  faceted.parse_parameters(prm, true);
  const MassSpringParameters f = MassSpringParameters::on_rough_mesh_body();
  EXPECT_EQ(faceted.contact_normal_damping_ratio, f.contact_normal_damping_ratio);
  EXPECT_EQ(faceted.time_step_update_frames, f.time_step_update_frames);
  EXPECT_EQ(faceted.net_force_tolerance, f.net_force_tolerance);
  // The faceted body's settle differs from the default one in every one of them.
  EXPECT_NE(f.contact_normal_damping_ratio, d.contact_normal_damping_ratio);
  EXPECT_NE(f.time_step_update_frames, d.time_step_update_frames);
  EXPECT_NE(f.net_force_tolerance, d.net_force_tolerance);

  prm.parse_input_from_string(
      "subsection Mass spring\n  set Time step update frames = 7\n"
      "  set Contact normal damping ratio = 0\nend\n");
  faceted.parse_parameters(prm, true);
  EXPECT_EQ(faceted.time_step_update_frames, 7);
  EXPECT_EQ(faceted.contact_normal_damping_ratio, 0.0);

  for (const char* bad : {"often", "2.5"}) {
    prm.parse_input_from_string(
        std::string("subsection Mass spring\n  set Time step update frames = ") + bad + "\nend\n");
    try {
      faceted.parse_parameters(prm, true);
      ADD_FAILURE() << "Time step update frames = " << bad << " was accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("Mass spring/Time step update frames"),
                std::string::npos)
          << e.what();
    }
  }
}

TEST(MassSpringParameters, TimeStepUpdateFramesAreReadAndNotNegative) {
  MassSpringParameters p = read_with("Time step update frames", "100", "-1");
  EXPECT_EQ(p.time_step_update_frames, 100);
  EXPECT_EQ(MassSpringParameters{}.time_step_update_frames, 0);
  p.time_step_update_frames = -1;
  expect_refused_naming(p, "Time step update frames");
}

TEST(MassSpringParameters, ContactNormalDampingRatioIsReadAndKeptWithinCritical) {
  MassSpringParameters p = read_with("Contact normal damping ratio", "0.5", "1.5");
  EXPECT_DOUBLE_EQ(p.contact_normal_damping_ratio, 0.5);
  EXPECT_EQ(MassSpringParameters{}.contact_normal_damping_ratio, 0.0);
  p.contact_normal_damping_ratio = -0.1;
  expect_refused_naming(p, "Contact normal damping ratio");
}

// The stick damper at auto: on (0.5) only for a garment arranged from the body's landmarks
// (round the limbs or the torso) on a faceted body mesh, off on a faceted body otherwise (the
// tops placed by Placement/Kind = dressing) and elsewhere; a number given wins; a ratio above
// critical or below zero is refused naming the entry.
TEST(MassSpringParameters, ContactStickDampingIsOnAtAutoOnlyRoundLimbsOnAFacetedBody) {
  dealii::ParameterHandler prm;
  MassSpringParameters::declare_parameters(prm);
  MassSpringParameters p;
  p.parse_parameters(prm, true, true);
  EXPECT_EQ(p.contact_stick_damping_ratio, 0.5);
  for (const auto& [faceted, arranged] : {std::pair{true, false}, {false, true}, {false, false}}) {
    p.parse_parameters(prm, faceted, arranged);
    EXPECT_EQ(p.contact_stick_damping_ratio, 0.0) << faceted << arranged;
  }
  EXPECT_EQ(MassSpringParameters{}.contact_stick_damping_ratio, 0.0);
  prm.parse_input_from_string(
      "subsection Mass spring\n  set Contact stick damping ratio = 0.2\nend\n");
  p.parse_parameters(prm, false, false);
  EXPECT_DOUBLE_EQ(p.contact_stick_damping_ratio, 0.2);
  for (double bad : {1.5, -0.1}) {
    p.contact_stick_damping_ratio = bad;
    expect_refused_naming(p, "Contact stick damping ratio");
  }
}

// The creep slide at auto: 50 1/s on a faceted body mesh with its net force rule, off elsewhere
// and where the net force rule is turned off (the creep is read on it); a number given wins.
TEST(MassSpringParameters, CreepSlideIsOnAtAutoOnAFacetedBodyWithANetForceRule) {
  dealii::ParameterHandler prm;
  MassSpringParameters::declare_parameters(prm);
  MassSpringParameters p;
  p.parse_parameters(prm, true);
  EXPECT_EQ(p.creep_slide_damping_per_s, 50.0);
  p.parse_parameters(prm, false);
  EXPECT_EQ(p.creep_slide_damping_per_s, 0.0);
  prm.parse_input_from_string("subsection Mass spring\n  set Net force tolerance = 0\nend\n");
  p.parse_parameters(prm, true);
  EXPECT_EQ(p.creep_slide_damping_per_s, 0.0);
  prm.parse_input_from_string(
      "subsection Mass spring\n  set Net force tolerance = 0.1\n  set Creep slide damping = "
      "20\nend\n");
  p.parse_parameters(prm, false);
  EXPECT_EQ(p.creep_slide_damping_per_s, 20.0);
  p.creep_slide_damping_per_s = -1;
  expect_refused_naming(p, "Creep slide damping");
}

TEST(MassSpringParameters, SlideDampingIsReadAndNeedsANetForceTolerance) {
  dealii::ParameterHandler prm;
  MassSpringParameters::declare_parameters(prm);
  prm.parse_input_from_string(
      "subsection Mass spring\n  set Slide damping = 50\n  set Net force tolerance = 0.05\nend\n");
  MassSpringParameters p;
  p.parse_parameters(prm);
  EXPECT_DOUBLE_EQ(p.slide_damping_per_s, 50.0);
  EXPECT_EQ(MassSpringParameters{}.slide_damping_per_s, 0.0);
  EXPECT_ANY_THROW(
      prm.parse_input_from_string("subsection Mass spring\n  set Slide damping = -1\nend\n"));
  // The slide's end is read against the net force limit: without one it is refused.
  p.net_force_tolerance = 0.0;
  expect_refused_naming(p, "Slide damping");
  p.net_force_tolerance = 0.05;
  p.slide_damping_per_s = -1.0;
  expect_refused_naming(p, "Slide damping");
}

}  // namespace
}  // namespace tightfit
