// Garment/Kind = pattern file: a garment cut from a sewing pattern file (SVG, GarmentCode
// JSON, AAMA DXF; docs/patterns.md), meshed by the Delaunay mesher and sewn by its seams.
#include "cases/parts/part_entries.h"
#include "pattern/pattern_file.h"
#include "pattern/pattern_garment.h"

#include <algorithm>
#include <cstdio>

namespace tightfit {

namespace {

// The case file's own declarations, added to what the file says. Returns the file's seams
// dropped with the panels left uncut.
std::vector<std::string> add_declarations(pattern::Pattern& p, ParameterTree& prm) {
  // Only the panels asked for (a top without its bindings, a torso without its sleeves),
  // before anything refers to them; the file's seams to the others are dropped (free edges).
  const std::vector<std::string> dropped = pattern::keep_panels(p, prm.get_list("Panels"));
  for (const auto& seam : pattern::parse_seam_list(prm.get("Seams"))) p.seams.push_back(seam);
  pattern::declare_folds(p, prm.get("Fold edges"));
  pattern::declare_mirrored(p, prm.get_list("Mirrored panels"));
  p.ease_weft = prm.get_double("Ease weft");
  p.ease_warp = prm.get_double("Ease warp");
  return dropped;
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
                       "Target triangle edge length of the Delaunay mesher (m), scaled by "
                       "Garment/Mesh scale; 0 takes Garment/Edge length weft (scaled too).");
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
    prm.declare_text("Size", "",
                     "The size to cut from a graded file (AAMA DXF: a block's SIZE text, e.g. "
                     "34); empty: the file must hold one size.");
    prm.declare_selection("Units", "from file", "from file|mm|cm|inch",
                          "The unit of a DXF file that does not say ($INSUNITS absent): 'from "
                          "file' takes $INSUNITS, else mm, refused when a piece would be under "
                          "2 cm or over 3 m across or the largest under 10 cm; a unit given "
                          "that contradicts $INSUNITS is refused.");
    prm.declare_text("Panels", "",
                     "The pattern's pieces to cut, a comma-separated list of panel names; "
                     "empty: every piece. The file's seams to pieces not cut are dropped "
                     "(listed in the garment's description) and their edges left free.");
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
    pattern::PatternFileOptions file_options;
    file_options.size = prm.get("Size");
    file_options.units = prm.get("Units") == "from file" ? "" : prm.get("Units");
    pattern::Pattern p = pattern::read_pattern_file(file, file_options);
    const std::vector<std::string> dropped = add_declarations(p, prm);
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
      if (!dropped.empty()) {
        garment.description += "; " + std::to_string(dropped.size()) +
                               " of the file's seams dropped with the panels not cut:";
        for (const std::string& seam : dropped) garment.description += " [" + seam + "]";
      }
      return garment;
    };
  };
  return e;
}

}  // namespace tightfit
