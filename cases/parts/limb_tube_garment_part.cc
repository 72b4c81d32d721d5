// Garment/Kind = limb tube: a tapered tube cut to a leg of the case's body from its landmarks
// (a graduated compression stocking; docs/stocking.md, "Cut to the leg"): its extent between
// two measuring points, the leg's tape girths normal to the leg's axis, the negative ease at
// measuring points. No coordinate of the body is written in the case.
#include "cases/limb_tube_cut.h"
#include "cases/parts/part_entries.h"
#include "cases/scenario_landmarks.h"
#include "core/tensile_curves.h"

#include <cstdio>

namespace tightfit {

namespace {

std::string end_text(const LimbTubeEnd& end) {
  char text[64];
  std::snprintf(text, sizeof text, "%s %c %.1f cm", end.point.c_str(), end.offset_m < 0 ? '-' : '+',
                100 * std::abs(end.offset_m));
  return text;
}

}  // namespace

PartEntry<GarmentMaker> limb_tube_garment_entry() {
  PartEntry<GarmentMaker> e;
  e.name = "limb tube";
  e.subsection = "Limb tube";
  e.description =
      "a tapered tube cut to a leg of the body from its landmarks: from one measuring point to "
      "another along the leg's axis, the leg's girths, a negative ease at measuring points (a "
      "graduated stocking; vertex groups bottom, top).";
  e.declare_parameters = [](ParameterTree& prm) {
    prm.declare_selection("Limb", "leg left", "leg left|leg right",
                          "The body part the tube is cut to and placed round (its axis, "
                          "docs/measuring-bodies.md).");
    prm.declare_text("From", "B - 0.02",
                     "The tube's bottom edge: POINT [+|- METRES], a measuring point of RAL-GZ "
                     "387 (B, B1, C, D, E, F, G; docs/stocking.md) and a distance up (+) or down "
                     "(-) the limb's axis from it (m).");
    prm.declare_text("To", "G + 0.04", "The tube's top edge, as From.");
    prm.declare_integer("Number of panels", 8, 1, 64,
                        "Equal panels sewn side by side round the tube (docs/model.md, 'Tapered "
                        "tubes').");
    prm.declare_double("Girth step", 0.05, 0.005, 1,
                       "The limb's girths are measured on sections normal to its axis at the "
                       "tube's ends, at every measuring point on it and this far apart between "
                       "(m).");
    prm.declare_text("Negative ease", "",
                     "POINT: EASE, ...: the share (-) by which the relaxed girth falls short of "
                     "the limb's girth at measuring points on the tube, linear in the height "
                     "between them and constant beyond: 'B: 0.25, G: 0.18'. Empty: none (the "
                     "tube's relaxed girths are the limb's).");
    prm.declare_text("Relaxed girths", "",
                     "HEIGHT:GIRTH, ...: the tube's own relaxed girths (m) at heights along it "
                     "from its bottom edge (m), replacing the limb's girths and the ease: a cut "
                     "designed by `tightfit design` (docs/design.md). Empty: the limb's girths "
                     "with the Negative ease.");
  };
  e.parse = [](ParameterTree& prm) -> GarmentMaker {
    const LimbTubeSpec spec =
        parse_limb_tube_spec(prm.get("Limb"), prm.get("From"), prm.get("To"),
                             prm.get_double("Girth step"), prm.get("Negative ease"));
    const int n_panels = prm.get_integer("Number of panels");
    const std::string relaxed_text = prm.get("Relaxed girths");
    PiecewiseLinear relaxed;
    if (relaxed_text.find_first_not_of(" \t") != std::string::npos) {
      std::vector<PiecewiseLinear::Point> points;
      for (const CurvePoint& p :
           parse_curve_points(relaxed_text, "Relaxed girths", "height:girth (e.g. 0.1:0.21)"))
        points.push_back({p.strain, p.value});
      relaxed = PiecewiseLinear(points, "Relaxed girths");
    }
    const std::string limb = prm.get("Limb");
    GarmentMaker maker;
    maker.make_on_body = [=](const std::string& name, const MeshSpacing& spacing,
                             const ScenarioBody& body) {
      const std::string where = "Garment/Limb tube: ";
      const TriangleSurface surface = scenario_body_surface(body);
      LimbTubeCut cut;
      try {
        cut = cut_tube_to_leg(surface, measure_body(surface), spec);
      } catch (const BodyMeasureError& error) {
        throw BodyMeasureError(where + "the tube is cut to the " + limb +
                               ", which needs the body's landmarks: " + error.what());
      } catch (const std::invalid_argument& error) {
        throw std::invalid_argument(where + error.what());
      }
      TaperedTubeShape shape;
      shape.length_m = cut.length_m;
      shape.n_panels = n_panels;
      if (!relaxed.points().empty()) {
        shape.girths_m = relaxed;
      } else {
        shape.girths_m = cut.girths_m;
        shape.negative_ease = cut.negative_ease;
      }
      try {
        shape.validate();
      } catch (const std::invalid_argument& error) {
        throw std::invalid_argument(where + error.what());
      }
      GarmentOnBody made{make_tapered_tube_garment(name, shape, spacing), {cut.middle_m(), cut.up}};
      char line[160];
      std::snprintf(line, sizeof line,
                    "%d panels sewn into a tube %.1f cm long cut to the %s from %s to %s; at its "
                    "measuring points, limb girth / relaxed girth (cm):",
                    n_panels, 100 * cut.length_m, limb.c_str(), end_text(spec.from).c_str(),
                    end_text(spec.to).c_str());
      std::string description = line;
      for (const PointValue& p : cut.points) {
        std::snprintf(line, sizeof line, " %s %.1f / %.1f", p.point.c_str(),
                      100 * cut.girths_m.at(p.value), 100 * shape.relaxed_girth_m(p.value));
        description += line;
      }
      made.garment.description = description;
      return made;
    };
    return maker;
  };
  return e;
}

}  // namespace tightfit
