// Garment/Kind = pattern file: a garment cut from a sewing pattern file (SVG, GarmentCode
// JSON, AAMA DXF; docs/patterns.md), meshed by the Delaunay mesher and sewn by its seams.
#include "cases/parts/part_entries.h"
#include "pattern/pattern_file.h"
#include "pattern/pattern_garment.h"

#include <algorithm>
#include <cstdio>

namespace tightfit {

namespace {

// The case file's own declarations, added to what the file says.
void add_declarations(pattern::Pattern& p, ParameterTree& prm) {
  // Only the panels asked for (a top without its bindings), before anything refers to them.
  const std::vector<std::string> kept = prm.get_list("Panels");
  for (const std::string& name : kept) {
    bool found = false;
    for (const auto& panel : p.panels) found = found || panel.name == name;
    if (!found)
      throw std::invalid_argument("Panels: the pattern has no panel '" + name + "'" +
                                  pattern::closest_panels(p, name));
  }
  if (!kept.empty())
    p.panels.erase(std::remove_if(p.panels.begin(), p.panels.end(),
                                  [&](const pattern::PanelOutline& panel) {
                                    return std::find(kept.begin(), kept.end(), panel.name) ==
                                           kept.end();
                                  }),
                   p.panels.end());
  for (const auto& seam : pattern::parse_seam_list(prm.get("Seams"))) p.seams.push_back(seam);
  pattern::declare_folds(p, prm.get("Fold edges"));
  pattern::declare_mirrored(p, prm.get_list("Mirrored panels"));
  p.ease_weft = prm.get_double("Ease weft");
  p.ease_warp = prm.get_double("Ease warp");
}

}  // namespace

PartEntry<GarmentMaker> pattern_file_garment_entry() {
  PartEntry<GarmentMaker> e;
  e.name = "pattern file";
  e.subsection = "Pattern file";
  e.description =
      "panels read from a sewing pattern (.svg, .json, .dxf), meshed and sewn "
      "(vertex groups: the pattern's edge names).";
  e.declare_parameters = [](ParameterTree& prm) {
    prm.declare_file_name("File", "",
                          "The pattern: FreeSewing SVG (.svg, mm), GarmentCode JSON (.json) or "
                          "AAMA DXF (.dxf); a relative path is read from the working directory, "
                          "else from the case file's folder.");
    prm.declare_double("Mesh edge length", 0, 0, ParameterTree::unbounded,
                       "Target triangle edge length of the Delaunay mesher (m); 0 takes "
                       "Garment/Edge length weft (scaled by Garment/Mesh scale).");
    prm.declare_double("Minimum angle", 25, 1, 33,
                       "No triangle angle below this (degrees; CGAL's mesher terminates up to "
                       "about 33).");
    prm.declare_double("Ease weft", 1, 0.01, 10,
                       "Scale factor of the pattern along the weft before sewing (-): below 1 "
                       "is negative ease, a garment smaller than its outline.");
    prm.declare_double("Ease warp", 1, 0.01, 10, "Scale factor along the warp (-).");
    prm.declare_bool("Rectangles as grids", true,
                     "Mesh a rectangle along its grain whose seams all join such rectangles as "
                     "the tube's regular grid (Garment/Edge length weft and warp), as "
                     "Garment/Kind = tube does.");
    prm.declare_text("Panels", "",
                     "The pattern's pieces to cut, a comma-separated list of panel names; "
                     "empty: every piece.");
    prm.declare_text("Seams", "",
                     "Seams besides the file's: 'PANEL:EDGE[+EDGE] [reversed] -- "
                     "PANEL:EDGE[+EDGE] [reversed]', separated by ';'. Each side's start meets "
                     "the other's start; 'reversed' walks a side against its outline.");
    prm.declare_text("Fold edges", "",
                     "Pieces cut on the fold: 'PANEL:EDGE, ...', each piece unfolded across "
                     "that (straight) edge; the mirrored edges are named 'EDGE mirrored'.");
    prm.declare_text("Mirrored panels", "",
                     "Pieces cut twice, the second mirrored: a comma-separated list of panels; "
                     "each copy is the panel 'NAME mirrored'.");
  };
  e.parse = [](ParameterTree& prm) -> GarmentMaker {
    const std::string file = prm.get_file_name("File");
    if (file.empty()) throw std::invalid_argument("File: no pattern file given");
    pattern::Pattern p = pattern::read_pattern_file(file);
    add_declarations(p, prm);
    pattern::validate(p);
    const double edge_length_m = prm.get_double("Mesh edge length");
    const double min_angle_deg = prm.get_double("Minimum angle");
    const bool grids = prm.get_bool("Rectangles as grids");
    return [=](const std::string& name, const MeshSpacing& spacing) {
      pattern::PatternMeshOptions options;
      options.edge_length_m = spacing.pattern_edge_length_m > 0 ? spacing.pattern_edge_length_m
                              : edge_length_m > 0               ? edge_length_m
                                                                : spacing.along_x_m;
      options.min_angle_deg = min_angle_deg;
      if (grids) options.rectangle_grid = spacing;
      Garment garment = pattern::pattern_garment(p, options);
      garment.name = name;
      char line[200];
      std::snprintf(line, sizeof line, "%zu panels and %zu seams from %s, ease %.3f x %.3f",
                    garment.panels.size(), garment.seams.size(), p.name.c_str(), p.ease_weft,
                    p.ease_warp);
      garment.description = line;
      return garment;
    };
  };
  return e;
}

}  // namespace tightfit
