// Placement/Kind = tube round axis: the tube already sewn, as a circle of a given radius round
// an axis (a cone's, or one through a mesh body's limb or waist), its middle at a given point.
// The radius must clear the body all round: a tube that starts inside the body stops the case
// (the scenario's start check, cases/scenario.h). A tube round the torso reads its centre, axis
// and radius from the body's landmarks as the dressing's frame does (cases/dressing_frame.h):
// Centre = torso at waist, Axis = vertical, Radius = waist + 0.02.
#include "bodies/tube_placement.h"
#include "cases/dressing_frame.h"
#include "cases/limb_tube_cut.h"
#include "cases/parts/part_entries.h"
#include "cases/scenario.h"
#include "cases/scenario_landmarks.h"
#include "core/closest_names.h"
#include "core/number_text.h"
#include "core/plain_text.h"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <optional>
#include <stdexcept>

namespace tightfit {

namespace {

const char* const section = "Placement/Tube round axis";
const std::vector<std::string> axis_words = {"body",      "garment",  "leg left",
                                             "leg right", "vertical", "torso"};

// Whether the entries name a line or the axis of the torso: the placement's centre, axis and
// radius then come from the dressing frame's resolution (cases/dressing_frame.h).
bool round_torso(const std::string& centre, const std::string& axis, const LineOffset& radius) {
  return trimmed(centre).rfind("torso", 0) == 0 || trimmed(axis) == "torso" || !radius.line.empty();
}

// Axis = leg left|right: the leg's line through B and G (cases/limb_tube_cut.h, as Garment/Kind
// = limb tube cuts along), the tube's lowest ring at `from` on it; the middle half the tube's
// length above.
GarmentLine tube_line_on_leg(const Scenario& s, int side, const LimbTubeEnd& from) {
  const TriangleSurface surface = scenario_body_surface(*s.body);
  try {
    const LegLine leg = leg_line(surface, measure_body(surface), side, "B", "G");
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (const auto& u : s.mesh.layout_positions_m) {
      low = std::min(low, u.y());
      high = std::max(high, u.y());
    }
    const double bottom_m = leg.axial_at(from, "From");
    return GarmentLine{leg.at(bottom_m + 0.5 * (high - low)), leg.up};
  } catch (const std::invalid_argument& e) {
    throw BodyMeasureError(std::string(section) + ": Axis = " + axis_words[2 + side] +
                           " needs the leg's landmarks: " + e.what());
  }
}

// The tube round the axis through `middle`: each ring `clearance_m` outside the body's section
// in its plane when that is positive, else at `radius_m` (or `stretch` times its rest radius).
std::vector<Vec3> place_round(Scenario& scenario, const Vec3& middle, const Vec3& axis,
                              double radius_m, double stretch, double clearance_m) {
  if (clearance_m > 0)
    return place_tube_round_limb(scenario.garment, scenario.mesh, middle, axis,
                                 scenario_body_surface(*scenario.body), clearance_m);
  return place_tube_round_axis(scenario.garment, scenario.mesh, middle, axis, radius_m, stretch);
}

}  // namespace

PartEntry<PlacementMaker> tube_round_axis_placement_entry() {
  PartEntry<PlacementMaker> e;
  e.name = "tube round axis";
  e.subsection = "Tube round axis";
  e.description =
      "the sewn tube as a circle of a given radius round an axis, its middle at a given point.";
  e.declare_parameters = [](ParameterTree& prm) {
    prm.declare_text("Centre", "0,0,0",
                     "Where the axis passes the middle of the tube: three numbers x,y,z (m), "
                     "'torso' (the torso axis's point at the crotch) or 'torso at LINE', where the "
                     "torso's axis reaches the line LINE (crotch, hips, waist, under-bust, bust, "
                     "armpit, neck base), from the body's landmarks (docs/measuring-bodies.md).");
    prm.declare_text("Axis", "body",
                     "Direction of the tube's axis, three numbers x,y,z (-), 'body' for the "
                     "body's own axis (a cone's or a cylinder's), 'garment' for the limb's "
                     "axis a garment cut to the body was cut along (Garment/Kind = limb tube), "
                     "the tube's middle then on it (Centre is not read), or 'leg left' / 'leg "
                     "right' for that leg's line through the centroids of its sections at B and "
                     "G, from the body's landmarks (docs/stocking.md), the tube's lower end at "
                     "From on it (Centre is not read); Constraints/Held direction = axis then "
                     "holds along it; 'vertical' for tightfit's z (the body's up), 'torso' for "
                     "the torso's axis from the body's landmarks.");
    prm.declare_text("From", "B - 0.02",
                     "With Axis = leg left|right: where the tube's lower end goes along the "
                     "leg's line, POINT [+|- METRES], a RAL-GZ 387 measuring point (B, B1, C, D, "
                     "E, F, G) and an offset up the leg (m).");
    prm.declare_text("Radius", "0.1",
                     "Radius of the tube's circle at the start: a number (m), larger than the "
                     "body wherever the tube lies, so that it shrinks onto it; or LINE + METRES "
                     "with LINE a girth line of the torso (hips, waist, under-bust, bust): the "
                     "farthest point of that line's tape path (its section's convex hull) from "
                     "the axis, across the body or front to back, plus METRES (m).");
    prm.declare_double("Stretch", 0, 0, ParameterTree::unbounded,
                       "If positive, each ring of the tube is placed at this many times its own "
                       "rest radius (its relaxed girth over 2 pi) instead of at Radius: a tapered "
                       "tube stretched evenly along its length (-). 0: every ring at Radius.");
    prm.declare_double("Clearance", 0, 0, ParameterTree::unbounded,
                       "If positive, each ring is centred on the centroid of the body's section "
                       "in its plane (normal to Axis, the section round the axis) and placed this "
                       "far outside that section's farthest point, instead of Radius and Stretch: "
                       "a tube that follows a bent limb (m; docs/stocking.md).");
  };
  e.parse = [](ParameterTree& prm) -> PlacementMaker {
    const std::string centre_text = prm.get("Centre");
    const std::string axis_text = prm.get("Axis");
    const LineOffset radius =
        parse_line_offset(prm.get("Radius"), "Radius", torso_girth_line_names());
    const double radius_m = radius.line.empty() ? radius.offset_m : 0.0;
    const double stretch = prm.get_double("Stretch");
    const double clearance_m = prm.get_double("Clearance");
    if (radius.line.empty() && !(radius_m > 0) && !(stretch > 0) && !(clearance_m > 0))
      throw std::invalid_argument("Radius must be positive (m)");
    if (round_torso(centre_text, axis_text, radius)) {
      // The dressing frame's centre and axis, its semi-axes both read at Radius: the circle
      // clears the line's tape path across the body and front to back.
      const DressingFrameSpec frame = parse_dressing_frame(
          centre_text, axis_text, "torso", prm.get("Radius"), prm.get("Radius"), "0");
      return [=](Scenario& scenario) {
        std::optional<BodyMeasurements> body;
        try {
          body = measure_body(scenario_body_surface(*scenario.body));
        } catch (const BodyMeasureError& e) {
          throw BodyMeasureError(std::string(section) +
                                 ": a tube round the torso (Centre = torso ..., Axis = torso, "
                                 "Radius = LINE + METRES) needs the body's landmarks; give "
                                 "Centre, Axis and Radius as numbers for a body without them: " +
                                 e.what());
        }
        PanelWrap wrap;
        try {
          wrap = resolve_dressing_frame(frame, &*body, 1.0);
        } catch (const std::invalid_argument& error) {
          throw std::invalid_argument(std::string(section) + ": " + error.what());
        }
        const double r_m = std::max(wrap.semi_axis_side_m, wrap.semi_axis_front_m);
        std::printf(
            "  tube round the torso: radius %.4f m round (%.4f, %.4f, %.4f) through "
            "(%.4f, %.4f, %.4f) m\n",
            r_m, wrap.axis.x(), wrap.axis.y(), wrap.axis.z(), wrap.centre_m.x(), wrap.centre_m.y(),
            wrap.centre_m.z());
        std::fflush(stdout);
        return place_round(scenario, wrap.centre_m, wrap.axis, r_m, stretch, clearance_m);
      };
    }
    const Vec3 centre = *parse_torso_or_vector(centre_text, "Centre");
    std::optional<Vec3> axis;
    const bool along_garment = axis_text == "garment";
    const int leg_side = axis_text == "leg left" ? 0 : axis_text == "leg right" ? 1 : -1;
    const LimbTubeEnd from = parse_limb_tube_end(prm.get("From"), "From");
    if (std::find(axis_words.begin(), axis_words.end(), axis_text) == axis_words.end()) {
      const std::vector<std::string> words = prm.get_list("Axis");
      std::vector<double> numbers;
      for (const std::string& w : words)
        if (const auto n = whole_number(w)) numbers.push_back(*n);
      if (words.size() != 3 || numbers.size() != 3)
        throw std::invalid_argument("Axis = '" + axis_text +
                                    "': expected three numbers x,y,z or one of body, garment, "
                                    "leg left, leg right, vertical, torso" +
                                    did_you_mean(trimmed(axis_text), axis_words, 0));
      axis = Vec3(numbers[0], numbers[1], numbers[2]);
      if (!(axis->norm() > 0)) throw std::invalid_argument("Axis must not be zero");
    } else if (axis_text == "vertical") {
      axis = Vec3::UnitZ();
    }
    return [=](Scenario& scenario) {
      if (leg_side >= 0) {
        // The line is the scenario's garment line from here on: Held direction = axis holds
        // along it (cases/scenario.cc).
        scenario.garment_line = tube_line_on_leg(scenario, leg_side, from);
      }
      if (along_garment && !scenario.garment_line)
        throw std::invalid_argument(
            "Placement/Tube round axis/Axis = garment, but the garment (Garment/Kind) is not cut "
            "along a limb's axis: give a direction x,y,z and a Centre");
      const bool on_line = along_garment || leg_side >= 0;
      const std::optional<Vec3> direction = on_line ? scenario.garment_line->axis
                                            : axis  ? axis
                                                    : scenario.body->axis();
      const Vec3 middle = on_line ? scenario.garment_line->centre_m : centre;
      if (!direction)
        throw std::invalid_argument("Placement/Tube round axis/Axis = body, but the body (" +
                                    scenario.body->describe() +
                                    ") has no axis: give a direction x,y,z");
      return place_round(scenario, middle, *direction, radius_m, stretch, clearance_m);
    };
  };
  return e;
}

}  // namespace tightfit
