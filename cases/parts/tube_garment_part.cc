// Garment/Kind = tube: equal rectangular panels sewn side by side into a closed tube (the
// paper's cylinder garments, Table 3).
#include "cases/parts/part_entries.h"
#include "core/tube_garment.h"

#include <cstdio>

namespace tightfit {

PartEntry<GarmentMaker> tube_garment_entry() {
  PartEntry<GarmentMaker> e;
  e.name = "tube";
  e.subsection = "Tube";
  e.description = "panels sewn side by side into a closed tube (vertex groups bottom, top).";
  e.declare_parameters = [](ParameterTree& prm) {
    prm.declare_double("Panel width", 0.1878, 1e-4, ParameterTree::unbounded,
                       "Width of each panel, round the tube, along the weft (m). The paper's "
                       "'4 5T': 0.1878; 'T': 0.157 (Table 3).");
    prm.declare_double("Panel height", 0.24, 1e-4, ParameterTree::unbounded,
                       "Height of each panel, along the tube, along the warp (m).");
    prm.declare_integer("Number of panels", 2, 1, 64,
                        "Panels sewn side by side into a closed tube; the rest circumference is "
                        "this number times the panel width.");
  };
  e.parse = [](ParameterTree& prm) -> GarmentMaker {
    const double width_m = prm.get_double("Panel width");
    const double height_m = prm.get_double("Panel height");
    const int n_panels = prm.get_integer("Number of panels");
    return [=](const std::string& name, const MeshSpacing& spacing) {
      Garment garment = make_tube_garment(name, width_m, height_m, n_panels, spacing);
      char line[160];
      std::snprintf(line, sizeof line,
                    "%d panels %.2f x %.2f cm sewn into a tube of rest circumference %.2f cm",
                    n_panels, 100 * width_m, 100 * height_m, 100 * n_panels * width_m);
      garment.description = line;
      return garment;
    };
  };
  return e;
}

}  // namespace tightfit
