// Placement/Kind = tube round axis: the tube already sewn, as a circle of a given radius round
// an axis (a cone's, or one through a mesh body's limb or waist), its middle at a given point.
// The radius must clear the body all round: a tube that starts inside the body stops the case
// (the scenario's start check, cases/scenario.h).
#include "bodies/tube_placement.h"
#include "cases/limb_tube_cut.h"
#include "cases/parts/part_entries.h"
#include "cases/scenario.h"
#include "cases/scenario_landmarks.h"
#include "core/closest_names.h"
#include "core/number_text.h"
#include "core/plain_text.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace tightfit {

namespace {

const char* const section = "Placement/Tube round axis";
const std::vector<std::string> axis_words = {"body", "garment", "leg left", "leg right"};

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

}  // namespace

PartEntry<PlacementMaker> tube_round_axis_placement_entry() {
  PartEntry<PlacementMaker> e;
  e.name = "tube round axis";
  e.subsection = "Tube round axis";
  e.description =
      "the sewn tube as a circle of a given radius round an axis, its middle at a given point.";
  e.declare_parameters = [](ParameterTree& prm) {
    prm.declare_vector("Centre", "0,0,0", "Where the axis passes the middle of the tube (m).");
    prm.declare_text("Axis", "body",
                     "Direction of the tube's axis, three numbers x,y,z (-), 'body' for the "
                     "body's own axis (a cone's or a cylinder's), 'garment' for the limb's "
                     "axis a garment cut to the body was cut along (Garment/Kind = limb tube), "
                     "the tube's middle then on it (Centre is not read), or 'leg left' / 'leg "
                     "right' for that leg's line through the centroids of its sections at B and "
                     "G, from the body's landmarks (docs/stocking.md), the tube's lower end at "
                     "From on it (Centre is not read); Constraints/Held direction = axis then "
                     "holds along it.");
    prm.declare_text("From", "B - 0.02",
                     "With Axis = leg left|right: where the tube's lower end goes along the "
                     "leg's line, POINT [+|- METRES], a RAL-GZ 387 measuring point (B, B1, C, D, "
                     "E, F, G) and an offset up the leg (m).");
    prm.declare_double("Radius", 0.1, 0, ParameterTree::unbounded,
                       "Radius of the tube's circle at the start (m): larger than the body "
                       "wherever the tube lies, so that it shrinks onto it.");
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
    const Vec3 centre = prm.get_vector("Centre");
    const std::string axis_text = prm.get("Axis");
    const double radius_m = prm.get_double("Radius");
    const double stretch = prm.get_double("Stretch");
    const double clearance_m = prm.get_double("Clearance");
    if (!(radius_m > 0) && !(stretch > 0) && !(clearance_m > 0))
      throw std::invalid_argument("Radius must be positive (m)");
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
                                    "leg left, leg right" +
                                    did_you_mean(trimmed(axis_text), axis_words, 0));
      axis = Vec3(numbers[0], numbers[1], numbers[2]);
      if (!(axis->norm() > 0)) throw std::invalid_argument("Axis must not be zero");
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
      if (clearance_m > 0) {
        const DisplayMesh body = scenario.body->body().display_mesh();
        TriangleSurface surface;
        surface.vertices_m = body.vertices_m;
        surface.triangles = body.triangles;
        return place_tube_round_limb(scenario.garment, scenario.mesh, middle, *direction, surface,
                                     clearance_m);
      }
      return place_tube_round_axis(scenario.garment, scenario.mesh, middle, *direction, radius_m,
                                   stretch);
    };
  };
  return e;
}

}  // namespace tightfit
