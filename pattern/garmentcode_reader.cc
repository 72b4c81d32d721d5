#include "pattern/garmentcode_reader.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <map>

namespace tightfit::pattern {

namespace {

using Json = nlohmann::json;

Vec2 vec2(const Json& value, const std::string& where) {
  if (!value.is_array() || value.size() != 2 || !value[0].is_number() || !value[1].is_number())
    throw PatternError(where + " is not a pair of numbers");
  return Vec2(value[0].get<double>(), value[1].get<double>());
}

Vec3 vec3(const Json& value, const std::string& where) {
  if (!value.is_array() || value.size() != 3) throw PatternError(where + " is not three numbers");
  Vec3 v;
  for (int k = 0; k < 3; ++k) {
    if (!value[k].is_number()) throw PatternError(where + " is not three numbers");
    v[k] = value[k].get<double>();
  }
  return v;
}

const Json& member(const Json& object, const char* key, const std::string& where) {
  if (!object.is_object() || !object.contains(key))
    throw PatternError(where + " has no '" + key + "'");
  return object.at(key);
}

// A control point given relative to the edge: a fraction along it and one across it (to the
// left of start -> end).
Vec2 absolute(const Vec2& start, const Vec2& end, const Vec2& relative) {
  const Vec2 along = end - start;
  return start + relative.x() * along + relative.y() * Vec2(-along.y(), along.x());
}

Segment curved(const Vec2& start, const Vec2& end, const Json& curvature, double scale,
               const std::string& where) {
  const std::string type = member(curvature, "type", where + " curvature").get<std::string>();
  const Json& params = member(curvature, "params", where + " curvature");
  if (!params.is_array()) throw PatternError(where + ": curvature params is not a list");
  if (type == "quadratic" && params.size() == 1)
    return quadratic_segment(start, absolute(start, end, vec2(params[0], where + " control")), end);
  if (type == "cubic" && params.size() == 2)
    return cubic_segment(start, absolute(start, end, vec2(params[0], where + " control 1")),
                         absolute(start, end, vec2(params[1], where + " control 2")), end);
  if (type == "circle" && params.size() == 3 && params[0].is_number()) {
    // [radius, large arc, right]: the arc of that radius (file units) from start to end, the
    // larger of the two when `large arc`, bulging to the right of start -> end when `right`.
    const double radius = params[0].get<double>() / scale;
    const double half_chord = 0.5 * (end - start).norm();
    if (!(radius >= half_chord))
      throw PatternError(where + ": circle radius " + std::to_string(radius) +
                         " m is shorter than half the edge");
    const double half_angle = std::asin(std::min(1.0, half_chord / radius));
    const double sweep = params[1].get<bool>() ? 2 * M_PI - 2 * half_angle : 2 * half_angle;
    return arc_segment_from_bulge(start, end,
                                  std::tan(sweep / 4) * (params[2].get<bool>() ? -1 : 1));
  }
  throw PatternError(where + ": unknown curvature '" + type + "' with " +
                     std::to_string(params.size()) + " parameters");
}

PanelOutline read_panel(const std::string& name, const Json& panel, double scale,
                        const std::string& file) {
  const std::string where = file + ": panel '" + name + "'";
  PanelOutline outline;
  outline.name = name;
  const Json& vertices_json = member(panel, "vertices", where);
  const Json& edges_json = member(panel, "edges", where);
  if (!vertices_json.is_array() || !edges_json.is_array())
    throw PatternError(where + ": vertices and edges must be lists");
  std::vector<Vec2> vertices;
  for (std::size_t k = 0; k < vertices_json.size(); ++k)
    vertices.push_back(vec2(vertices_json[k], where + " vertex " + std::to_string(k)) / scale);
  double twice_area = 0.0;
  for (std::size_t k = 0; k < vertices.size(); ++k) {
    const Vec2& a = vertices[k];
    const Vec2& b = vertices[(k + 1) % vertices.size()];
    twice_area += a.x() * b.y() - b.x() * a.y();
  }
  // Clockwise: seen from inside. Mirror left to right to see it from outside.
  const bool mirror = twice_area < 0;
  const Mat2 to_outside = mirror ? Mat2(Vec2(-1, 1).asDiagonal()) : Mat2::Identity();

  std::map<std::string, int> label_count;
  for (const Json& e : edges_json)
    if (e.is_object() && e.contains("label") && e["label"].is_string())
      ++label_count[e["label"].get<std::string>()];
  for (std::size_t k = 0; k < edges_json.size(); ++k) {
    const Json& e = edges_json[k];
    const std::string at = where + " edge " + std::to_string(k);
    const Json& ends = member(e, "endpoints", at);
    if (!ends.is_array() || ends.size() != 2 || !ends[0].is_number_integer() ||
        !ends[1].is_number_integer())
      throw PatternError(at + ": endpoints is not a pair of vertex indices");
    const int i = ends[0].get<int>(), j = ends[1].get<int>();
    const int n = static_cast<int>(vertices.size());
    if (i < 0 || i >= n || j < 0 || j >= n)
      throw PatternError(at + ": endpoint index out of range (the panel has " + std::to_string(n) +
                         " vertices)");
    Segment s = e.contains("curvature")
                    ? curved(vertices[i], vertices[j], e["curvature"], scale, at)
                    : line_segment(vertices[i], vertices[j]);
    Edge edge;
    const bool labelled = e.contains("label") && e["label"].is_string() &&
                          label_count[e["label"].get<std::string>()] == 1;
    edge.name = labelled ? e["label"].get<std::string>() : std::to_string(k);
    edge.segments.push_back(transformed(s, to_outside, Vec2::Zero()));
    outline.edges.push_back(edge);
  }
  PanelPlacement3D placement;
  if (panel.contains("translation"))
    placement.translation_m = vec3(panel["translation"], where + " translation") / scale;
  if (panel.contains("rotation"))
    placement.rotation_xyz_deg = vec3(panel["rotation"], where + " rotation");
  outline.placement = placement;
  return outline;
}

EdgeRange stitch_side(const Json& side, const Pattern& pattern, const std::string& where) {
  const std::string panel = member(side, "panel", where).get<std::string>();
  const Json& edge = member(side, "edge", where);
  if (!edge.is_number_integer()) throw PatternError(where + ": edge is not an index");
  const PanelOutline& outline = find_panel(pattern, panel);
  const int k = edge.get<int>();
  if (k < 0 || k >= static_cast<int>(outline.edges.size()))
    throw PatternError(where + ": panel '" + panel + "' has no edge " + std::to_string(k));
  return {panel, {outline.edges[k].name}, false};
}

}  // namespace

Pattern read_garmentcode_json(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw PatternError("cannot open the pattern file '" + path + "'");
  Json root;
  try {
    root = Json::parse(in);
  } catch (const Json::parse_error& error) {
    throw PatternError(path + ": not valid JSON (" + error.what() + ")");
  }
  try {
    Pattern pattern;
    pattern.name = path.substr(path.find_last_of('/') + 1);
    double scale = 100.0;
    if (root.contains("properties") && root["properties"].contains("units_in_meter"))
      scale = root["properties"]["units_in_meter"].get<double>();
    if (!(scale > 0)) throw PatternError(path + ": units_in_meter must be positive");
    const Json& spec = member(root, "pattern", path);
    const Json& panels = member(spec, "panels", path + ": pattern");
    if (!panels.is_object() || panels.empty())
      throw PatternError(path + ": pattern.panels is not a non-empty object");
    std::vector<std::string> order;
    if (spec.contains("panel_order"))
      order = spec["panel_order"].get<std::vector<std::string>>();
    else
      for (const auto& item : panels.items()) order.push_back(item.key());
    for (const std::string& name : order)
      pattern.panels.push_back(
          read_panel(name, member(panels, name.c_str(), path + ": pattern.panels"), scale, path));
    if (spec.contains("stitches")) {
      const Json& stitches = spec["stitches"];
      for (std::size_t k = 0; k < stitches.size(); ++k) {
        const std::string where = path + ": stitch " + std::to_string(k);
        if (!stitches[k].is_array() || stitches[k].size() != 2)
          throw PatternError(where + " is not a pair of edges");
        SeamSpec seam{stitch_side(stitches[k][0], pattern, where),
                      stitch_side(stitches[k][1], pattern, where)};
        seam.b.reversed = true;  // both outlines counter-clockwise: the edges run opposite
        pattern.seams.push_back(seam);
      }
    }
    return pattern;
  } catch (const Json::exception& error) {
    throw PatternError(path + ": " + error.what());
  }
}

}  // namespace tightfit::pattern
