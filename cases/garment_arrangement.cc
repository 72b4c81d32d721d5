#include "cases/garment_arrangement.h"
#include "core/closest_names.h"

#include "core/plain_text.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace tightfit {

namespace {

const std::vector<std::string> torso_parts = {"torso front", "torso left", "torso back",
                                              "torso right"};

std::string lower(std::string text) {
  for (char& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

bool is_torso(const std::string& part) {
  return part == "torso" ||
         std::find(torso_parts.begin(), torso_parts.end(), part) != torso_parts.end();
}

// Round the axis from the front towards the body's left (bodies/panel_wrap.h's angles).
double torso_part_angle_rad(const std::string& part) {
  const auto k = std::find(torso_parts.begin(), torso_parts.end(), part) - torso_parts.begin();
  return 0.5 * M_PI * double(k);
}

struct PanelExtent {
  double x_min = 0, x_max = 0, y_min = 0, y_max = 0;
  double width() const { return x_max - x_min; }
};

PanelExtent extent(const Panel& panel) {
  PanelExtent e;
  if (panel.rest_positions_m.empty()) return e;
  e.x_min = e.x_max = panel.rest_positions_m.front().x();
  e.y_min = e.y_max = panel.rest_positions_m.front().y();
  for (const Vec2& r : panel.rest_positions_m) {
    e.x_min = std::min(e.x_min, r.x());
    e.x_max = std::max(e.x_max, r.x());
    e.y_min = std::min(e.y_min, r.y());
    e.y_max = std::max(e.y_max, r.y());
  }
  return e;
}

// The top of panel p's side seam, pattern y: of its seams to another torso panel, the most
// upright edge (height over width above one), the tallest; NaN without one.
double side_seam_top_y(const Garment& garment, int p, const std::vector<std::string>& parts) {
  double best_height = 0.0, top = std::numeric_limits<double>::quiet_NaN();
  const Panel& panel = garment.panels[p];
  for (const Seam& seam : garment.seams) {
    for (int side = 0; side < 2; ++side) {
      const int here = side == 0 ? seam.panel_a : seam.panel_b;
      const int there = side == 0 ? seam.panel_b : seam.panel_a;
      if (here != p || there == p || !is_torso(parts[there])) continue;
      const auto edge = panel.edges.find(side == 0 ? seam.edge_a : seam.edge_b);
      if (edge == panel.edges.end() || edge->second.empty()) continue;
      double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
      for (int v : edge->second) {
        const Vec2& r = panel.rest_positions_m[v];
        x0 = std::min(x0, r.x()), x1 = std::max(x1, r.x());
        y0 = std::min(y0, r.y()), y1 = std::max(y1, r.y());
      }
      if (y1 - y0 > x1 - x0 && y1 - y0 > best_height) {
        best_height = y1 - y0;
        top = y1;
      }
    }
  }
  return top;
}

// The torso's girth lines the body has, from the bust down.
std::vector<const BodyGirth*> torso_girths(const BodyMeasurements& body) {
  std::vector<const BodyGirth*> found;
  for (const char* name : {"bust", "under-bust", "waist", "hips"}) {
    try {
      found.push_back(&body.girth(name));
    } catch (const std::out_of_range&) {
    }
  }
  return found;
}

double level_m(const PartFrame& torso, const Vec3& point_m) {
  return (point_m - torso.origin_m).dot(torso.along);
}

}  // namespace

const std::vector<std::string>& arrangement_body_parts() {
  static const std::vector<std::string> parts = {"torso front", "torso back", "torso left",
                                                 "torso right", "arm left",   "arm right",
                                                 "leg left",    "leg right"};
  return parts;
}

std::map<std::string, std::string> parse_arrangement_parts(const std::vector<std::string>& words) {
  std::map<std::string, std::string> parts;
  const auto& known = arrangement_body_parts();
  for (const std::string& word : words) {
    const auto colon = word.rfind(':');
    if (colon == std::string::npos)
      throw std::invalid_argument("Body parts: '" + word + "' is not PANEL: PART");
    const std::string panel = trimmed(word.substr(0, colon));
    const std::string part = trimmed(word.substr(colon + 1));
    if (std::find(known.begin(), known.end(), part) == known.end()) {
      std::string list;
      for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
      throw std::invalid_argument("Body parts: '" + part + "' (panel '" + panel +
                                  "') is no body part; one of " + list +
                                  did_you_mean(part, known, 0));
    }
    parts[panel] = part;
  }
  return parts;
}

std::string arrangement_part_from_name(const std::string& panel_name) {
  const std::string name = lower(panel_name);
  const auto has = [&](const char* word) { return name.find(word) != std::string::npos; };
  const std::string side = has("left") ? "left" : has("right") ? "right" : "";
  if (has("sleeve") || has("arm")) return side.empty() ? "" : "arm " + side;
  if (has("leg") || has("pant") || has("trouser")) return side.empty() ? "" : "leg " + side;
  if (has("front")) return "torso front";
  if (has("back")) return "torso back";
  if (has("side") && !side.empty()) return "torso " + side;
  return "";
}

ArrangementPlan plan_arrangement(const Garment& garment, const BodyMeasurements& body,
                                 const ArrangementOptions& options) {
  const std::size_t n = garment.panels.size();
  if (n == 0) throw std::invalid_argument("the garment has no panels to arrange");
  std::vector<std::string> panel_names;
  for (const Panel& p : garment.panels) panel_names.push_back(p.name);
  for (const auto& [panel, part] : options.parts)
    if (std::find(panel_names.begin(), panel_names.end(), panel) == panel_names.end())
      throw std::invalid_argument("Body parts: the garment has no panel '" + panel + "'" +
                                  did_you_mean(panel, panel_names));
  ArrangementPlan plan;
  plan.panel_parts.resize(n);
  bool any = false;
  for (std::size_t p = 0; p < n; ++p) {
    const auto given = options.parts.find(garment.panels[p].name);
    plan.panel_parts[p] = given != options.parts.end()
                              ? given->second
                              : arrangement_part_from_name(garment.panels[p].name);
    any = any || !plan.panel_parts[p].empty();
  }
  for (std::size_t p = 0; p < n; ++p) {
    if (!any)
      plan.panel_parts[p] = "torso";  // evenly round, below
    else if (plan.panel_parts[p].empty())
      throw std::invalid_argument("Body parts: panel '" + garment.panels[p].name +
                                  "' names no body part; give it one (PANEL: PART)");
    if (plan.panel_parts[p].rfind("arm", 0) == 0 || plan.panel_parts[p].rfind("leg", 0) == 0)
      throw std::invalid_argument(
          "Body parts: panel '" + garment.panels[p].name + "' goes on the " + plan.panel_parts[p] +
          ", but the arrangement dresses the torso alone (the body shrinks about the torso's "
          "axis, where no sleeve or leg finds room); cut the torso's panels (Panels)");
  }

  const PartFrame& torso = body.part("torso");
  PanelWrap& wrap = plan.wrap;
  wrap.centre_m = torso.origin_m;
  wrap.axis = torso.along;
  wrap.front = torso.front;
  // The torso's extent across its axis at its girth lines, and its largest girth.
  double side_m = 0.0, front_m = 0.0, girth_m = 0.0;
  for (const BodyGirth* g : torso_girths(body)) {
    girth_m = std::max(girth_m, g->girth_m);
    for (const Vec3& q : g->hull_m) {
      const Vec3 d = q - torso.origin_m;
      side_m = std::max(side_m, std::abs(d.dot(torso.lateral)));
      front_m = std::max(front_m, std::abs(d.dot(torso.front)));
    }
  }
  if (!(girth_m > 0))
    throw std::invalid_argument("the body has none of the torso's girths (bust, waist, hips)");
  const double clearance_m = options.clearance * girth_m / (2 * M_PI);
  wrap.semi_axis_side_m = options.start_scale * side_m + clearance_m;
  wrap.semi_axis_front_m = options.start_scale * front_m + clearance_m;
  const double radius_m =
      ellipse_perimeter_m(wrap.semi_axis_side_m, wrap.semi_axis_front_m) / (2 * M_PI);

  // Round the axis: the panels of one side of the torso side by side, centred on that side.
  wrap.panel_angles_rad.assign(n, 0.0);
  if (!any) {
    for (std::size_t p = 0; p < n; ++p) wrap.panel_angles_rad[p] = 2 * M_PI * double(p) / double(n);
  } else {
    for (const std::string& part : torso_parts) {
      double total_m = 0.0;
      for (std::size_t p = 0; p < n; ++p)
        if (plan.panel_parts[p] == part) total_m += extent(garment.panels[p]).width();
      double start_m = -0.5 * total_m;
      for (std::size_t p = 0; p < n; ++p) {
        if (plan.panel_parts[p] != part) continue;
        const double w = extent(garment.panels[p]).width();
        wrap.panel_angles_rad[p] = torso_part_angle_rad(part) + (start_m + 0.5 * w) / radius_m;
        start_m += w;
      }
    }
  }

  // Heights: each side seam's top a little below the lower armpit.
  plan.armpit_level_m = std::min(level_m(torso, body.landmark("armpit left").point_m),
                                 level_m(torso, body.landmark("armpit right").point_m));
  const double seam_top_m = plan.armpit_level_m - options.side_seam_below_armpit_m;
  wrap.panel_hem_heights_m.assign(n, std::numeric_limits<double>::quiet_NaN());
  double sum = 0.0;
  int found = 0;
  for (std::size_t p = 0; p < n; ++p) {
    const double top = side_seam_top_y(garment, int(p), plan.panel_parts);
    if (std::isnan(top)) continue;
    wrap.panel_hem_heights_m[p] = seam_top_m - (top - extent(garment.panels[p]).y_min);
    sum += wrap.panel_hem_heights_m[p];
    ++found;
  }
  // Without side seams: the panels' tops at the neck's base.
  const double neck_m = level_m(torso, body.landmark("neck base").point_m);
  for (std::size_t p = 0; p < n; ++p)
    if (std::isnan(wrap.panel_hem_heights_m[p])) {
      const PanelExtent e = extent(garment.panels[p]);
      wrap.panel_hem_heights_m[p] = found > 0 ? sum / found : neck_m - (e.y_max - e.y_min);
    }

  char line[300];
  std::snprintf(line, sizeof line,
                "round the torso's axis, semi-axes %.3f m (side) and %.3f m (front) about the "
                "body shrunk to %.2f; the side seams' tops %.3f m below the armpits:",
                wrap.semi_axis_side_m, wrap.semi_axis_front_m, options.start_scale,
                options.side_seam_below_armpit_m);
  plan.description = line;
  for (std::size_t p = 0; p < n; ++p) {
    std::snprintf(line, sizeof line, "%s %s on the %s at %.0f degrees, hem %.3f m above the crotch",
                  p == 0 ? "" : ";", garment.panels[p].name.c_str(), plan.panel_parts[p].c_str(),
                  wrap.panel_angles_rad[p] * 180.0 / M_PI, wrap.panel_hem_heights_m[p]);
    plan.description += line;
  }
  return plan;
}

double panel_width_at_m(const Panel& panel, double y_m) {
  std::vector<std::pair<double, double>> cuts;
  for (const Triangle& t : panel.triangles) {
    double lo = 1e300, hi = -1e300;
    for (int k = 0; k < 3; ++k) {
      const Vec2& a = panel.rest_positions_m[t[k]];
      const Vec2& b = panel.rest_positions_m[t[(k + 1) % 3]];
      if ((a.y() - y_m) * (b.y() - y_m) > 0 || a.y() == b.y()) continue;
      const double x = a.x() + (b.x() - a.x()) * (y_m - a.y()) / (b.y() - a.y());
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
    if (hi > lo) cuts.emplace_back(lo, hi);
  }
  std::sort(cuts.begin(), cuts.end());
  double width = 0.0, end = -1e300;
  for (const auto& [lo, hi] : cuts) {
    if (hi <= end) continue;
    width += hi - std::max(lo, end);
    end = hi;
  }
  return width;
}

BodyEase parse_body_ease(const std::string& text) {
  const auto colon = text.find(':');
  BodyEase ease;
  if (colon != std::string::npos) {
    ease.line = trimmed(text.substr(0, colon));
    try {
      std::size_t used = 0;
      const std::string number = text.substr(colon + 1);
      ease.ease = std::stod(number, &used);
      if (number.find_first_not_of(" \t", used) == std::string::npos && ease.ease > -1 &&
          !ease.line.empty())
        return ease;
    } catch (const std::exception&) {
    }
  }
  throw std::invalid_argument("Ease against body: '" + text +
                              "' is not LINE: EASE (a girth line and the garment round the body "
                              "over the body's girth there, less one, above -1: bust: -0.15)");
}

std::vector<EaseAtLine> ease_at_girth_lines(const Garment& garment, const ArrangementPlan& plan,
                                            const BodyMeasurements& body) {
  std::vector<EaseAtLine> lines;
  const PartFrame& torso = body.part("torso");
  for (const BodyGirth* g : torso_girths(body)) {
    const double level = level_m(torso, g->centre_m);
    EaseAtLine at;
    at.line = g->name;
    at.girth_m = g->girth_m;
    bool reached = true;
    for (std::size_t p = 0; p < garment.panels.size(); ++p) {
      if (!is_torso(plan.panel_parts[p])) continue;
      const PanelExtent e = extent(garment.panels[p]);
      const double y = e.y_min + level - plan.wrap.panel_hem_heights_m[p];
      const double w = panel_width_at_m(garment.panels[p], y);
      reached = reached && w > 0;
      at.garment_m += w;
    }
    if (!reached) continue;
    at.ease = at.garment_m / at.girth_m - 1.0;
    lines.push_back(at);
  }
  return lines;
}

double round_body_scale_for(const BodyEase& ease, const Garment& garment,
                            const ArrangementPlan& plan, const BodyMeasurements& body) {
  try {
    body.girth(ease.line);
  } catch (const std::out_of_range&) {
    throw std::invalid_argument(
        "Ease against body: the body has no girth line '" + ease.line +
        "' (bust, under-bust, waist, hips)" +
        did_you_mean(ease.line, {"bust", "under-bust", "waist", "hips"}, 0));
  }
  for (const EaseAtLine& at : ease_at_girth_lines(garment, plan, body))
    if (at.line == ease.line) return at.girth_m * (1.0 + ease.ease) / at.garment_m;
  throw std::invalid_argument("Ease against body: the garment, as arranged, does not reach the " +
                              ease.line + " line all round the body");
}

void scale_panels_round_body(Garment& garment, double factor) {
  for (Panel& panel : garment.panels) {
    const PanelExtent e = extent(panel);
    const double middle = 0.5 * (e.x_min + e.x_max);
    for (Vec2& r : panel.rest_positions_m) r.x() = middle + factor * (r.x() - middle);
  }
}

}  // namespace tightfit
