// Any pattern file by its extension, and the declarations a case file adds to it (seams,
// folds, mirrored copies, ease) for formats that do not carry them.
#pragma once

#include "pattern/pattern.h"

#include <string>

namespace tightfit::pattern {

// .svg (FreeSewing), .json (GarmentCode), .dxf (AAMA); `options` choose the size and unit of
// a DXF file and are refused for the others, which say both. Throws PatternError for another
// extension or a broken file.
Pattern read_pattern_file(const std::string& path, const PatternFileOptions& options = {});

// The sizes a graded file holds (AAMA DXF: its blocks' SIZE text); empty for other formats.
std::vector<std::string> pattern_file_sizes(const std::string& path);

// Keeps only the panels named (none: all) and the file's seams between them; returns the
// seams dropped ("PANEL:EDGE -- PANEL:EDGE"), whose kept sides become free edges (hems).
// Throws PatternError naming a panel the pattern does not have.
std::vector<std::string> keep_panels(Pattern& pattern, const std::vector<std::string>& names);

// "front:3 -- back:3 mirrored reversed; front:2+3 -- back:2+3": seams separated by ';', each
// two sides joined by "--", a side "PANEL:EDGE[+EDGE...]" walked along the outline, or
// against it when followed by the word "reversed". Throws PatternError for a malformed list.
std::vector<SeamSpec> parse_seam_list(const std::string& text);

// "front:1, back:1": panel and edge pairs separated by commas.
std::vector<std::pair<std::string, std::string>> parse_panel_edges(const std::string& text);

// Marks the pieces cut on the fold ("PANEL:EDGE, ...") and those cut twice mirrored (panel
// names). Throws PatternError naming a panel that does not exist.
void declare_folds(Pattern& pattern, const std::string& panel_edges);
void declare_mirrored(Pattern& pattern, const std::vector<std::string>& panels);

}  // namespace tightfit::pattern
