// Garment/Kind = sheet: one flat rectangular panel, nothing sewn.
#include "cases/parts/part_entries.h"

#include <cstdio>

namespace tightfit {

PartEntry<GarmentMaker> sheet_garment_entry() {
  PartEntry<GarmentMaker> e;
  e.name = "sheet";
  e.subsection = "Sheet";
  e.description = "one flat rectangular panel (vertex groups bottom, top, left, right).";
  e.declare_parameters = [](ParameterTree& prm) {
    prm.declare_double("Width", 0.2, 1e-4, ParameterTree::unbounded,
                       "Width of the sheet along the weft (m).");
    prm.declare_double("Height", 0.2, 1e-4, ParameterTree::unbounded,
                       "Height of the sheet along the warp (m).");
  };
  e.parse = [](ParameterTree& prm) -> GarmentMaker {
    const double width_m = prm.get_double("Width");
    const double height_m = prm.get_double("Height");
    return [=](const std::string& name, const MeshSpacing& spacing) {
      Garment garment;
      garment.name = name;
      garment.panels.push_back(make_rectangle_panel(name, width_m, height_m, spacing));
      char line[120];
      std::snprintf(line, sizeof line, "one flat sheet %.2f x %.2f cm", 100 * width_m,
                    100 * height_m);
      garment.description = line;
      return garment;
    };
  };
  return e;
}

}  // namespace tightfit
