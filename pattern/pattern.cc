#include "pattern/pattern.h"

#include "core/closest_names.h"

#include <set>

namespace tightfit::pattern {

double length_m(const std::vector<Segment>& segments) {
  return ArcLengthCurve(segments).length_m();
}

const PanelOutline& find_panel(const Pattern& pattern, const std::string& name) {
  for (const PanelOutline& p : pattern.panels)
    if (p.name == name) return p;
  throw PatternError("pattern '" + pattern.name + "': no panel '" + name + "'" +
                     closest_panels(pattern, name));
}

std::vector<std::string> panel_names(const Pattern& pattern) {
  std::vector<std::string> names;
  for (const PanelOutline& p : pattern.panels) names.push_back(p.name);
  return names;
}

std::string closest_panels(const Pattern& pattern, const std::string& unknown) {
  return did_you_mean(unknown, panel_names(pattern));
}

int find_edge(const PanelOutline& panel, const std::string& name) {
  for (std::size_t e = 0; e < panel.edges.size(); ++e)
    if (panel.edges[e].name == name) return static_cast<int>(e);
  return -1;
}

std::vector<Segment> range_segments(const PanelOutline& panel, const EdgeRange& range) {
  std::vector<Segment> segments;
  for (const std::string& name : range.edges) {
    const int e = find_edge(panel, name);
    if (e < 0) throw PatternError("panel '" + panel.name + "' has no edge '" + name + "'");
    const auto& edge = panel.edges[e].segments;
    if (!range.reversed)
      segments.insert(segments.end(), edge.begin(), edge.end());
    else
      for (auto s = edge.rbegin(); s != edge.rend(); ++s) segments.push_back(reversed(*s));
  }
  return segments;
}

namespace {

void validate_panel(const PanelOutline& panel, double tolerance_m) {
  const std::string where = "panel '" + panel.name + "'";
  if (panel.name.empty()) throw PatternError("a panel has no name");
  if (panel.edges.size() < 2)
    throw PatternError(where + ": an outline needs at least two edges, it has " +
                       std::to_string(panel.edges.size()));
  std::set<std::string> names;
  for (std::size_t e = 0; e < panel.edges.size(); ++e) {
    const Edge& edge = panel.edges[e];
    const std::string at = where + ", edge '" + edge.name + "'";
    if (edge.name.empty())
      throw PatternError(where + ": edge " + std::to_string(e) + " has no name");
    if (!names.insert(edge.name).second)
      throw PatternError(where + ": two edges are named '" + edge.name + "'");
    if (edge.segments.empty()) throw PatternError(at + " has no segment");
    for (std::size_t s = 1; s < edge.segments.size(); ++s)
      if ((edge.segments[s].start - edge.segments[s - 1].end).norm() > tolerance_m)
        throw PatternError(at + ": segment " + std::to_string(s) +
                           " does not start where the one before ends");
    if (!(length_m(edge.segments) > tolerance_m)) throw PatternError(at + " has zero length");
    const Edge& next = panel.edges[(e + 1) % panel.edges.size()];
    const double gap = (next.segments.front().start - edge.segments.back().end).norm();
    if (gap > tolerance_m)
      throw PatternError(where + ": the outline is open between edge '" + edge.name +
                         "' and edge '" + next.name + "' (gap " + std::to_string(gap) + " m)");
  }
  if (!panel.fold_edge.empty()) {
    const int f = find_edge(panel, panel.fold_edge);
    if (f < 0) throw PatternError(where + ": no fold edge '" + panel.fold_edge + "'");
    for (const Segment& s : panel.edges[f].segments)
      if (s.kind != Segment::Kind::line || std::abs((s.end - s.start)
                                                        .normalized()
                                                        .dot((panel.edges[f].segments.back().end -
                                                              panel.edges[f].segments.front().start)
                                                                 .normalized())) < 1 - 1e-9)
        throw PatternError(where + ": fold edge '" + panel.fold_edge + "' is not straight");
  }
}

}  // namespace

namespace {
void validate_seams(const Pattern& pattern);
}

void validate(const Pattern& pattern, double tolerance_m) {
  if (pattern.panels.empty()) throw PatternError("pattern '" + pattern.name + "' has no panel");
  if (!(pattern.ease_weft > 0) || !(pattern.ease_warp > 0))
    throw PatternError("pattern '" + pattern.name + "': ease factors must be positive");
  std::set<std::string> panel_names;
  for (const PanelOutline& panel : pattern.panels) {
    validate_panel(panel, tolerance_m);
    if (!panel_names.insert(panel.name).second)
      throw PatternError("pattern '" + pattern.name + "': two panels are named '" + panel.name +
                         "'");
  }
  validate_seams(cut_pieces(pattern));
}

namespace {

void validate_seams(const Pattern& pattern) {
  // Every edge in at most one seam side; a range's edges follow each other round the outline.
  std::set<std::pair<std::string, std::string>> sewn;
  for (std::size_t k = 0; k < pattern.seams.size(); ++k) {
    const std::string seam = "seam " + std::to_string(k + 1);
    for (const EdgeRange* side : {&pattern.seams[k].a, &pattern.seams[k].b}) {
      if (side->edges.empty()) throw PatternError(seam + " has a side with no edge");
      const PanelOutline* panel = nullptr;
      for (const PanelOutline& p : pattern.panels)
        if (p.name == side->panel) panel = &p;
      if (!panel)
        throw PatternError(seam + " names panel '" + side->panel + "', which does not exist" +
                           closest_panels(pattern, side->panel));
      const int n = static_cast<int>(panel->edges.size());
      int previous = -1;
      for (const std::string& name : side->edges) {
        const int e = find_edge(*panel, name);
        if (e < 0) {
          std::vector<std::string> edges;
          for (const auto& edge : panel->edges) edges.push_back(edge.name);
          throw PatternError(seam + " names edge '" + name + "' of panel '" + panel->name +
                             "', which does not exist" + did_you_mean(name, edges));
        }
        if (name == panel->fold_edge)
          throw PatternError(seam + " sews fold edge '" + name + "' of panel '" + panel->name +
                             "'");
        if (previous >= 0 && e != (previous + (side->reversed ? n - 1 : 1)) % n)
          throw PatternError(seam + ": edge '" + name + "' of panel '" + panel->name +
                             "' does not follow the edge before it along the outline");
        if (!sewn.insert({panel->name, name}).second)
          throw PatternError(seam + " sews edge '" + name + "' of panel '" + panel->name +
                             "', which another seam already sews");
        previous = e;
      }
    }
  }
}

}  // namespace

}  // namespace tightfit::pattern
