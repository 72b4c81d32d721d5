#include "pattern/garmentcode_reader.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <map>

namespace tightfit::pattern {

namespace {

using Json = nlohmann::json;

// Every value is checked before use, so that a wrong type names its place and key instead of
// surfacing as a bare JSON type error.
std::string type_of(const Json& value) {
  return value.type_name();
}

const Json& member(const Json& object, const char* key, const std::string& where) {
  if (!object.is_object()) throw PatternError(where + " is not an object");
  if (!object.contains(key)) throw PatternError(where + " has no '" + key + "'");
  return object.at(key);
}

double number(const Json& value, const std::string& where, const std::string& key) {
  if (!value.is_number())
    throw PatternError(where + ": '" + key + "' must be a number, not " + type_of(value));
  const double x = value.get<double>();
  if (!std::isfinite(x)) throw PatternError(where + ": '" + key + "' is not finite");
  return x;
}

// A flag as GarmentCode writes it: true/false, or 0/1 (numpy booleans written as integers).
bool flag(const Json& value, const std::string& where, const std::string& key) {
  if (value.is_boolean()) return value.get<bool>();
  if (value.is_number() && (value.get<double>() == 0 || value.get<double>() == 1))
    return value.get<double>() == 1;
  throw PatternError(where + ": '" + key + "' must be true/false or 0/1, not " +
                     (value.is_number() ? value.dump() : type_of(value)));
}

Vec2 vec2(const Json& value, const std::string& where, const std::string& key) {
  if (!value.is_array() || value.size() != 2)
    throw PatternError(
        where + ": '" + key + "' must be a pair of numbers, not " +
        (value.is_array() ? std::to_string(value.size()) + " values" : type_of(value)));
  return Vec2(number(value[0], where, key), number(value[1], where, key));
}

Vec3 vec3(const Json& value, const std::string& where, const std::string& key) {
  if (!value.is_array() || value.size() != 3)
    throw PatternError(where + ": '" + key + "' must be three numbers");
  return Vec3(number(value[0], where, key), number(value[1], where, key),
              number(value[2], where, key));
}

int index(const Json& value, const std::string& where, const std::string& key) {
  if (!value.is_number() || value.get<double>() != std::floor(value.get<double>()) ||
      std::abs(value.get<double>()) > 1e9)
    throw PatternError(where + ": '" + key + "' must be a whole number, not " +
                       (value.is_number() ? value.dump() : type_of(value)));
  return static_cast<int>(value.get<double>());
}

std::string text(const Json& value, const std::string& where, const std::string& key) {
  if (!value.is_string())
    throw PatternError(where + ": '" + key + "' must be a string, not " + type_of(value));
  return value.get<std::string>();
}

// How control points are given: relative to the edge (a fraction along it and one across
// it, to the left of start -> end), or in the panel's own coordinates.
enum class Coordinates { relative, absolute };

Vec2 control_point(const Vec2& start, const Vec2& end, const Vec2& given, Coordinates coords,
                   double scale) {
  if (coords == Coordinates::absolute) return given / scale;
  const Vec2 along = end - start;
  return start + given.x() * along + given.y() * Vec2(-along.y(), along.x());
}

// The curvature forms GarmentCode writes: {"type": "quadratic", "params": [[x, y]]},
// {"type": "cubic", "params": [[x1, y1], [x2, y2]]}, {"type": "circle", "params": [radius,
// large_arc, right]} (flags true/false or 0/1), and the older bare [x, y] (a quadratic's
// control point).
Segment curved(const Vec2& start, const Vec2& end, const Json& curvature, Coordinates coords,
               double scale, const std::string& where) {
  if (curvature.is_array())
    return quadratic_segment(
        start, control_point(start, end, vec2(curvature, where, "curvature"), coords, scale), end);
  const std::string type = text(member(curvature, "type", where + " curvature"), where, "type");
  const Json& params = member(curvature, "params", where + " curvature");
  if (!params.is_array())
    throw PatternError(where + ": 'params' must be a list, not " + type_of(params));
  auto point = [&](std::size_t k) {
    return control_point(start, end, vec2(params[k], where, "params"), coords, scale);
  };
  if (type == "quadratic" && params.size() == 1) return quadratic_segment(start, point(0), end);
  if (type == "cubic" && params.size() == 2) return cubic_segment(start, point(0), point(1), end);
  if (type == "circle" && params.size() == 3) {
    // [radius, large arc, right]: the arc of that radius (file units) from start to end, the
    // larger of the two when `large arc`, bulging to the right of start -> end when `right`
    // (GarmentCode: right is the arc's midpoint on the right, its relative y below 0; as an
    // SVG arc in y-up coordinates its sweep is counter-clockwise).
    const double radius = number(params[0], where, "params[0] (radius)") / scale;
    const bool large_arc = flag(params[1], where, "params[1] (large arc)");
    const bool right = flag(params[2], where, "params[2] (right)");
    const double half_chord = 0.5 * (end - start).norm();
    if (!(radius >= half_chord * (1 - 1e-9)))
      throw PatternError(where + ": circle radius " + std::to_string(radius) +
                         " m is shorter than half the edge");
    const double half_angle = std::asin(std::min(1.0, half_chord / radius));
    const double sweep = large_arc ? 2 * M_PI - 2 * half_angle : 2 * half_angle;
    // A positive bulge turns counter-clockwise, bulging to the right (segment.h).
    return arc_segment_from_bulge(start, end, std::tan(sweep / 4) * (right ? 1 : -1));
  }
  throw PatternError(where + ": unknown curvature '" + type + "' with " +
                     std::to_string(params.size()) + " parameters");
}

PanelOutline read_panel(const std::string& name, const Json& panel, double scale,
                        Coordinates coords, bool normalize_translation, const std::string& file) {
  const std::string where = file + ": panel '" + name + "'";
  PanelOutline outline;
  outline.name = name;
  const Json& vertices_json = member(panel, "vertices", where);
  const Json& edges_json = member(panel, "edges", where);
  if (!vertices_json.is_array()) throw PatternError(where + ": 'vertices' must be a list");
  if (!edges_json.is_array()) throw PatternError(where + ": 'edges' must be a list");
  std::vector<Vec2> vertices;
  for (std::size_t k = 0; k < vertices_json.size(); ++k)
    vertices.push_back(vec2(vertices_json[k], where + " vertex " + std::to_string(k), "vertices") /
                       scale);
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
    if (!ends.is_array() || ends.size() != 2)
      throw PatternError(at + ": 'endpoints' must be a pair of vertex indices");
    const int i = index(ends[0], at, "endpoints"), j = index(ends[1], at, "endpoints");
    const int n = static_cast<int>(vertices.size());
    if (i < 0 || i >= n || j < 0 || j >= n)
      throw PatternError(at + ": endpoint index out of range (the panel has " + std::to_string(n) +
                         " vertices)");
    const bool has_curvature = e.contains("curvature") && !e["curvature"].is_null();
    Segment s = has_curvature ? curved(vertices[i], vertices[j], e["curvature"], coords, scale, at)
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
    placement.translation_m = vec3(panel["translation"], where, "translation") / scale;
  if (panel.contains("rotation")) {
    const Json& rotation = panel["rotation"];
    if (rotation.is_array() && rotation.size() == 3 && rotation[0].is_array())
      throw PatternError(where +
                         ": 'rotation' as a 3 x 3 matrix is not read; give XYZ Euler "
                         "angles in degrees");
    placement.rotation_xyz_deg = vec3(rotation, where, "rotation");
  }
  if (normalize_translation && !vertices.empty()) {
    // GarmentCode moves each panel's origin to its vertices' mean and adds that offset to
    // the translation's x and y as written.
    Vec2 mean = Vec2::Zero();
    for (const Vec2& v : vertices) mean += v / static_cast<double>(vertices.size());
    placement.translation_m += Vec3(mean.x(), mean.y(), 0.0);
  }
  placement.outline_mirrored = mirror;
  outline.placement = placement;
  return outline;
}

EdgeRange stitch_side(const Json& side, const Pattern& pattern, const std::string& where) {
  const std::string panel = text(member(side, "panel", where), where, "panel");
  const int k = index(member(side, "edge", where), where, "edge");
  const PanelOutline* outline = nullptr;
  for (const PanelOutline& p : pattern.panels)
    if (p.name == panel) outline = &p;
  if (!outline) throw PatternError(where + ": no panel '" + panel + "'");
  if (k < 0 || k >= static_cast<int>(outline->edges.size()))
    throw PatternError(where + ": panel '" + panel + "' has no edge " + std::to_string(k));
  return {panel, {outline->edges[k].name}, false};
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
    // GarmentCode's properties: units (cm when absent, as GarmentCode assumes), how control
    // points are given, whether panel translations are to be re-centred.
    double scale = 100.0;
    Coordinates coords = Coordinates::relative;
    bool normalize_translation = false;
    const std::string props = path + ": properties";
    if (root.is_object() && root.contains("properties")) {
      const Json& properties = root["properties"];
      if (!properties.is_object()) throw PatternError(props + " is not an object");
      if (properties.contains("units_in_meter"))
        scale = number(properties["units_in_meter"], props, "units_in_meter");
      if (properties.contains("curvature_coords")) {
        const std::string c = text(properties["curvature_coords"], props, "curvature_coords");
        if (c != "relative" && c != "absolute")
          throw PatternError(props + ": 'curvature_coords' must be relative or absolute, not '" +
                             c + "'");
        coords = c == "absolute" ? Coordinates::absolute : Coordinates::relative;
      }
      if (properties.contains("normalize_panel_translation"))
        normalize_translation =
            flag(properties["normalize_panel_translation"], props, "normalize_panel_translation");
    }
    if (!(scale > 0)) throw PatternError(path + ": units_in_meter must be positive");
    const Json& spec = member(root, "pattern", path);
    const Json& panels = member(spec, "panels", path + ": pattern");
    if (!panels.is_object() || panels.empty())
      throw PatternError(path + ": pattern.panels is not a non-empty object");
    std::vector<std::string> order;
    if (spec.contains("panel_order")) {
      const Json& listed = spec["panel_order"];
      if (!listed.is_array()) throw PatternError(path + ": 'panel_order' must be a list");
      for (const Json& name : listed)
        if (!name.is_null())  // GarmentCode leaves null for a panel it removed
          order.push_back(text(name, path + ": panel_order", "panel_order"));
    } else {
      for (const auto& item : panels.items()) order.push_back(item.key());
    }
    for (const std::string& name : order)
      pattern.panels.push_back(read_panel(name,
                                          member(panels, name.c_str(), path + ": pattern.panels"),
                                          scale, coords, normalize_translation, path));
    if (spec.contains("stitches")) {
      const Json& stitches = spec["stitches"];
      if (!stitches.is_array()) throw PatternError(path + ": 'stitches' must be a list");
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
