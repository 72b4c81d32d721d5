// Garment/Kind = tapered tube: a tube whose relaxed girth changes along its length, given at
// heights (a graduated compression stocking or sleeve; core/tapered_tube_garment.h).
#include "cases/parts/part_entries.h"
#include "core/tapered_tube_garment.h"
#include "core/tensile_curves.h"

#include <cstdio>

namespace tightfit {

namespace {

PiecewiseLinear parse_profile(const std::string& text, const std::string& entry,
                              const std::string& form) {
  std::vector<PiecewiseLinear::Point> points;
  for (const CurvePoint& p : parse_curve_points(text, entry, form))
    points.push_back({p.strain, p.value});
  return PiecewiseLinear(points, entry);
}

}  // namespace

PartEntry<GarmentMaker> tapered_tube_garment_entry() {
  PartEntry<GarmentMaker> e;
  e.name = "tapered tube";
  e.subsection = "Tapered tube";
  e.description =
      "a tube whose relaxed girth changes linearly between given heights (a graduated stocking; "
      "vertex groups bottom, top).";
  e.declare_parameters = [](ParameterTree& prm) {
    prm.declare_double("Length", 0.24, 1e-4, ParameterTree::unbounded,
                       "Relaxed length of the tube, along the warp (m).");
    prm.declare_integer("Number of panels", 8, 1, 64,
                        "Equal panels sewn side by side round the tube; more panels keep each "
                        "one's slanted sides closer to the warp (docs/model.md, 'Tapered "
                        "tubes').");
    prm.declare_text("Girths", "0:0.30, 0.24:0.36",
                     "HEIGHT:GIRTH, ...: girths (m) at heights along the tube from its bottom "
                     "edge (m, increasing, within Length), linear between them and constant "
                     "beyond. Without Negative ease these are the relaxed girths; with it, the "
                     "body's girths the tube is cut to.");
    prm.declare_text("Negative ease", "",
                     "HEIGHT:EASE, ...: the share (-) by which the relaxed girth falls short of "
                     "the body's girth at each height (m along the tube), linear between them: "
                     "relaxed girth = Girths x (1 - ease); 0.2 cuts the tube 20% smaller than "
                     "the body. Empty: the girths are the relaxed girths.");
  };
  e.parse = [](ParameterTree& prm) -> GarmentMaker {
    TaperedTubeShape shape;
    shape.length_m = prm.get_double("Length");
    shape.n_panels = prm.get_integer("Number of panels");
    shape.girths_m = parse_profile(prm.get("Girths"), "Girths", "height:girth (e.g. 0.1:0.21)");
    const std::string ease = prm.get("Negative ease");
    if (ease.find_first_not_of(" \t") != std::string::npos)
      shape.negative_ease = parse_profile(ease, "Negative ease", "height:ease (e.g. 0.1:0.25)");
    shape.validate();
    return [=](const std::string& name, const MeshSpacing& spacing) {
      Garment garment = make_tapered_tube_garment(name, shape, spacing);
      char line[200];
      std::snprintf(line, sizeof line,
                    "%d panels sewn into a tube %.1f cm long, relaxed girth %.1f cm at its bottom "
                    "to %.1f cm at its top",
                    shape.n_panels, 100 * shape.length_m, 100 * shape.relaxed_girth_m(0.0),
                    100 * shape.relaxed_girth_m(shape.length_m));
      garment.description = line;
      return garment;
    };
  };
  return e;
}

}  // namespace tightfit
