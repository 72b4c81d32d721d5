#include "pattern/pattern_file.h"

#include "core/closest_names.h"
#include "core/plain_text.h"

#include "pattern/dxf_reader.h"
#include "pattern/garmentcode_reader.h"
#include "pattern/svg_reader.h"

#include <algorithm>
#include <cctype>

namespace tightfit::pattern {

namespace {

std::string lower_extension(const std::string& path) {
  const auto dot = path.find_last_of('.');
  std::string ext = dot == std::string::npos ? "" : path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

std::vector<std::string> split(const std::string& text, const std::string& separator) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (;;) {
    const auto at = text.find(separator, start);
    parts.push_back(trimmed(text.substr(start, at - start)));
    if (at == std::string::npos) return parts;
    start = at + separator.size();
  }
}

std::pair<std::string, std::string> panel_and_rest(const std::string& text,
                                                   const std::string& what) {
  const auto colon = text.find(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 == text.size())
    throw PatternError(what + " '" + text + "' is not PANEL:EDGE");
  return {trimmed(text.substr(0, colon)), trimmed(text.substr(colon + 1))};
}

EdgeRange parse_side(std::string text) {
  EdgeRange side;
  const std::string word = " reversed";
  if (text.size() > word.size() &&
      text.compare(text.size() - word.size(), word.size(), word) == 0) {
    side.reversed = true;
    text = trimmed(text.substr(0, text.size() - word.size()));
  }
  const auto [panel, edges] = panel_and_rest(text, "seam side");
  side.panel = panel;
  side.edges = split(edges, "+");
  for (const std::string& e : side.edges)
    if (e.empty()) throw PatternError("seam side '" + text + "' names an empty edge");
  return side;
}

}  // namespace

Pattern read_pattern_file(const std::string& path, const PatternFileOptions& options) {
  const std::string ext = lower_extension(path);
  if (ext == "dxf") return read_aama_dxf(path, options);
  if (ext != "svg" && ext != "json")
    throw PatternError("pattern file '" + path + "': unknown format '." + ext +
                       "' (known: .svg, .json, .dxf)");
  if (!options.size.empty())
    throw PatternError(path + ": a size ('" + options.size +
                       "') is chosen, but only DXF files hold several sizes");
  if (!options.units.empty())
    throw PatternError(path + ": a unit ('" + options.units + "') is given, but " +
                       (ext == "svg" ? "SVG patterns are in mm" : "GarmentCode files say theirs") +
                       " (units_in_meter)");
  return ext == "svg" ? read_freesewing_svg(path) : read_garmentcode_json(path);
}

std::vector<std::string> pattern_file_sizes(const std::string& path) {
  return lower_extension(path) == "dxf" ? aama_dxf_sizes(path) : std::vector<std::string>{};
}

namespace {

std::string side_text(const EdgeRange& side) {
  std::string text = side.panel + ":";
  for (std::size_t k = 0; k < side.edges.size(); ++k) text += (k ? "+" : "") + side.edges[k];
  return text + (side.reversed ? " reversed" : "");
}

}  // namespace

std::vector<std::string> keep_panels(Pattern& pattern, const std::vector<std::string>& names) {
  if (names.empty()) return {};
  auto kept = [&](const std::string& panel) {
    return std::find(names.begin(), names.end(), panel) != names.end();
  };
  for (const std::string& name : names) {
    bool found = false;
    for (const auto& panel : pattern.panels) found = found || panel.name == name;
    if (!found) {
      std::string all;
      for (const auto& panel : pattern.panels) all += (all.empty() ? "" : ", ") + panel.name;
      throw PatternError("pattern '" + pattern.name + "' has no panel '" + name + "'" +
                         did_you_mean(name, panel_names(pattern), 0) + " (its panels: " + all +
                         ")");
    }
  }
  pattern.panels.erase(std::remove_if(pattern.panels.begin(), pattern.panels.end(),
                                      [&](const PanelOutline& panel) { return !kept(panel.name); }),
                       pattern.panels.end());
  std::vector<std::string> dropped;
  std::vector<SeamSpec> seams;
  for (const SeamSpec& seam : pattern.seams) {
    if (kept(seam.a.panel) && kept(seam.b.panel))
      seams.push_back(seam);
    else
      dropped.push_back(side_text(seam.a) + " -- " + side_text(seam.b));
  }
  pattern.seams = seams;
  return dropped;
}

std::vector<SeamSpec> parse_seam_list(const std::string& text) {
  std::vector<SeamSpec> seams;
  if (trimmed(text).empty()) return seams;
  for (const std::string& seam : split(text, ";")) {
    if (seam.empty()) continue;
    const auto sides = split(seam, "--");
    if (sides.size() != 2)
      throw PatternError("seam '" + seam + "' does not join two sides with --");
    seams.push_back({parse_side(sides[0]), parse_side(sides[1])});
  }
  return seams;
}

std::vector<std::pair<std::string, std::string>> parse_panel_edges(const std::string& text) {
  std::vector<std::pair<std::string, std::string>> list;
  if (trimmed(text).empty()) return list;
  for (const std::string& item : split(text, ",")) list.push_back(panel_and_rest(item, "entry"));
  return list;
}

namespace {

PanelOutline& panel_named(Pattern& pattern, const std::string& name, const std::string& what) {
  for (auto& outline : pattern.panels)
    if (outline.name == name) return outline;
  throw PatternError(what + ": no panel '" + name + "'" + closest_panels(pattern, name));
}

}  // namespace

void declare_folds(Pattern& pattern, const std::string& panel_edges) {
  for (const auto& [panel, edge] : parse_panel_edges(panel_edges))
    panel_named(pattern, panel, "fold edges").fold_edge = edge;
}

void declare_mirrored(Pattern& pattern, const std::vector<std::string>& panels) {
  for (const std::string& panel : panels)
    panel_named(pattern, panel, "mirrored panels").mirrored_copy = true;
}

}  // namespace tightfit::pattern
