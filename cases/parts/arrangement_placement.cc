// Placement/Kind = arrangement: the dressing of Placement/Kind = dressing with every coordinate
// read off the body (cases/garment_arrangement.h): each panel assigned to a side of the torso
// by the case's short list or its name, wrapped round the torso's axis at a clearance from its
// girths, its side seam's top under the armpits; optionally the pattern scaled round the body
// to an ease stated against one of the body's girths (docs/arrangement.md).
#include "body/body_measurements.h"
#include "cases/coarse_dressing.h"
#include "cases/failed_dressing_output.h"
#include "cases/garment_arrangement.h"
#include "cases/parts/part_entries.h"
#include "cases/scenario.h"
#include "contact/penalty_contact.h"
#include "core/backend_registry.h"
#include "core/number_text.h"

#include <cstdio>
#include <iostream>
#include <optional>
#include <stdexcept>

namespace tightfit {

namespace {

const char* const section = "Placement/Arrangement";

struct ArrangementSettings {
  ArrangementOptions options;
  std::optional<BodyEase> ease;
  DressingSettings dressing;
  // Coarse edge length, m: 0 dresses the case's mesh itself; unset (auto) chooses it from the
  // case's mesh (coarse_edge_length_m).
  std::optional<double> coarse_m;
};

// Coarse edge length = auto (docs/arrangement.md, "Parameters"): a pattern meshed at 15 mm or
// finer is dressed at 4/3 of its edge length and carried; a coarser one is dressed itself. The
// dressing's 2000 frames then run on about 0.57 of the vertices at a third longer time step.
constexpr double auto_coarse_below_m = 0.015;

double coarse_edge_length_m(const ArrangementSettings& a, const Scenario& s) {
  if (a.coarse_m) return *a.coarse_m;
  const double edge_m = s.parameters.garment.spacing.pattern_edge_length_m;
  if (s.parameters.garment.kind != "pattern file" || !(edge_m > 0)) return 0.0;
  return edge_m <= auto_coarse_below_m * (1 + 1e-9) ? edge_m * 4.0 / 3.0 : 0.0;
}

BodyMeasurements measured_body(const Scenario& scenario) {
  const DisplayMesh mesh = scenario.body->body().display_mesh();
  TriangleSurface surface;
  surface.vertices_m = mesh.vertices_m;
  surface.triangles = mesh.triangles;
  try {
    return measure_body(surface);
  } catch (const BodyMeasureError& e) {
    throw BodyMeasureError(std::string(section) +
                           ": the arrangement needs the body's landmarks: " + e.what());
  }
}

// The scenario's garment cut `factor` times its width round the body: welded again, with the
// mesh's edge length and the penalty stiffness that follow from it (scenario.cc).
void refit_round_body(Scenario& s, double factor) {
  scale_panels_round_body(s.garment, factor);
  char line[80];
  std::snprintf(line, sizeof line, "; fitted to the body: x %.3f round it", factor);
  s.garment.description += line;
  s.mesh = weld(s.garment);
  s.mean_edge_length_m = mean_rest_edge_length_m(s.mesh);
  s.problem.contact_stiffness_Pa_per_m = penalty_stiffness_Pa_per_m(
      s.parameters.penalty_factor, s.law->stiffness_scale(), s.mean_edge_length_m);
  s.problem.tangential_stiffness_Pa_per_m =
      s.parameters.tangential_penalty_ratio * s.problem.contact_stiffness_Pa_per_m;
}

void print_ease(const std::vector<EaseAtLine>& lines) {
  std::printf("  arrangement: ease against the body (garment round the body / body's girth - 1):");
  for (const EaseAtLine& at : lines)
    std::printf("%s %s %.1f %% (%.3f m / %.3f m)", &at == &lines.front() ? "" : ";",
                at.line.c_str(), 100.0 * at.ease, at.garment_m, at.girth_m);
  std::printf("\n");
}

// The placement itself; `fixed_scale`: the round-body factor already found on the case's own
// mesh (the coarse mesh takes it, so that both meshes are cut alike).
PlacementMaker arrange(const ArrangementSettings& a, std::optional<double> fixed_scale) {
  return [=](Scenario& s) -> std::vector<Vec3> {
    const BodyMeasurements body = measured_body(s);
    ArrangementPlan plan;
    try {
      plan = plan_arrangement(s.garment, body, a.options);
      double factor = 1.0;
      if (fixed_scale)
        factor = *fixed_scale;
      else if (a.ease)
        factor = round_body_scale_for(*a.ease, s.garment, plan, body);
      if (factor != 1.0) {
        refit_round_body(s, factor);
        plan = plan_arrangement(s.garment, body, a.options);
      }
      if (!fixed_scale) {
        std::printf("  arrangement: %s\n", plan.description.c_str());
        const std::vector<EaseAtLine> lines = ease_at_girth_lines(s.garment, plan, body);
        if (!lines.empty()) print_ease(lines);
        std::fflush(stdout);
      }
      const double coarse_m = fixed_scale ? 0.0 : coarse_edge_length_m(a, s);
      if (coarse_m > 0) {
        ArrangementSettings coarse = a;
        coarse.coarse_m = 0.0;
        return dressed_from_coarse(s, coarse_m, CoarseSettle{}, arrange(coarse, factor), section);
      }
    } catch (const BodyMeasureError&) {
      throw;
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string(section) + ": " + e.what());
    }
    DressingSettings settings = a.dressing;
    settings.centre_m = plan.wrap.centre_m;
    settings.scale_axis = plan.wrap.axis;
    write_failed_dressing_to(s.parameters.output, settings);
    const std::vector<Vec3> open = wrap_panels_round_axis(s.garment, s.mesh, plan.wrap);
    try {
      const DressingResult dressed =
          backend_registry().dressing_stage().dress(s.problem, s.garment, open, settings);
      print_dressing(dressed);
      return dressed.welded_positions_m;
    } catch (const std::invalid_argument& error) {
      throw std::invalid_argument(std::string(section) + ": " + error.what());
    }
  };
}

}  // namespace

PartEntry<PlacementMaker> arrangement_placement_entry() {
  PartEntry<PlacementMaker> e;
  e.name = "arrangement";
  e.subsection = "Arrangement";
  e.description =
      "the dressing with its start read off the body's landmarks: each panel on a side of the "
      "torso, wrapped round the torso's axis, its side seam under the armpits; optionally "
      "fitted to an ease against the body's girth (docs/arrangement.md).";
  e.declare_parameters = [](ParameterTree& prm) {
    prm.declare_text("Body parts", "",
                     "Where each panel goes: 'PANEL: PART, ...' with PART one of torso front, "
                     "torso back, torso left, torso right; a panel not listed goes where its "
                     "name says (front, back, side left/right); a garment none of whose panels "
                     "is placed either way goes evenly round the torso.");
    prm.declare_text("Ease against body", "",
                     "'LINE: EASE': the pattern is scaled round the body (pattern x) so that the "
                     "garment's width round the body at the girth line LINE (bust, under-bust, "
                     "waist, hips) is (1 + EASE) times the body's girth there (-0.15: 15 % "
                     "smaller); empty: the pattern as cut. The ease at every girth line the "
                     "garment reaches is printed.");
    prm.declare_double("Start scale", 0.7, 0.05, 1,
                       "The body's scale about the torso's axis at the start of the dressing "
                       "(-).");
    prm.declare_double("Clearance", 0.1, 0, 10,
                       "The panels' cylinder outside the shrunk torso by this share of the largest "
                       "torso girth's mean radius, girth / 2 pi (-).");
    prm.declare_double("Side seam below armpit", 0.03, -1, 1,
                       "The top of each panel's side seam (its most upright seam to another "
                       "torso panel) this far below the lower armpit along the torso's axis (m).");
    declare_dressing_frames(prm);
    prm.declare_text("Coarse edge length", "auto",
                     "Above 0: dress the garment meshed at this edge length (m) and carry its "
                     "welded state to the case's mesh in pattern space; 0: dress the case's "
                     "mesh itself; auto: 4/3 of Garment/Pattern file/Mesh edge length when that "
                     "is 15 mm or finer, else 0.");
  };
  e.parse = [](ParameterTree& prm) -> PlacementMaker {
    ArrangementSettings a;
    a.options.parts = parse_arrangement_parts(prm.get_list("Body parts"));
    const std::string ease = prm.get("Ease against body");
    if (ease.find_first_not_of(" \t") != std::string::npos) a.ease = parse_body_ease(ease);
    a.options.start_scale = prm.get_double("Start scale");
    a.options.clearance = prm.get_double("Clearance");
    a.options.side_seam_below_armpit_m = prm.get_double("Side seam below armpit");
    a.coarse_m = auto_or_number(prm.get("Coarse edge length"), "Coarse edge length");
    if (a.coarse_m && !(*a.coarse_m >= 0))
      throw std::invalid_argument("Coarse edge length: must be auto or a length >= 0 (m)");
    a.dressing.start_scale = a.options.start_scale;
    read_dressing_frames(prm, a.dressing);
    a.dressing.progress = &std::cout;
    return arrange(a, std::nullopt);
  };
  return e;
}

}  // namespace tightfit
