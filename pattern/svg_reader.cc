#include "pattern/svg_reader.h"

#include <pugixml.hpp>

#include <cctype>
#include <cstdlib>
#include <cstring>

namespace tightfit::pattern {

namespace {

// Reads the numbers and commands of an SVG path's data one at a time.
class PathData {
 public:
  PathData(const char* text, std::string where) : p_(text), where_(std::move(where)) {}

  // The next command letter, or the previous one repeated when numbers follow; 0 at the end.
  char command(char previous) {
    skip_separators();
    if (*p_ == '\0') return 0;
    if (std::isalpha(static_cast<unsigned char>(*p_))) return *p_++;
    if (previous == 0 || previous == 'Z' || previous == 'z')
      throw PatternError(where_ + ": path data starts with a number, not a command");
    return previous == 'M' ? 'L' : previous == 'm' ? 'l' : previous;
  }
  double number() {
    skip_separators();
    char* end = nullptr;
    const double value = std::strtod(p_, &end);
    if (end == p_)
      throw PatternError(where_ + ": expected a number at '" + std::string(p_).substr(0, 20) + "'");
    p_ = end;
    return value;
  }
  Vec2 point() {
    const double x = number();
    return Vec2(x, number());
  }

 private:
  void skip_separators() {
    while (*p_ == ',' || std::isspace(static_cast<unsigned char>(*p_))) ++p_;
  }
  const char* p_;
  std::string where_;
};

std::vector<Segment> parse_path(const char* d, const std::string& where) {
  PathData data(d, where);
  std::vector<Segment> segments;
  Vec2 current = Vec2::Zero(), start = Vec2::Zero();
  char command = 0;
  bool started = false;
  while ((command = data.command(command)) != 0) {
    const bool relative = std::islower(static_cast<unsigned char>(command));
    const Vec2 origin = relative ? current : Vec2::Zero();
    const char upper = static_cast<char>(std::toupper(static_cast<unsigned char>(command)));
    if (upper != 'M' && !started) throw PatternError(where + ": path data does not start with M");
    switch (upper) {
      case 'M':
        if (started) throw PatternError(where + ": a second subpath (M) in a piece's outline");
        current = start = origin + data.point();
        started = true;
        break;
      case 'L': {
        const Vec2 end = origin + data.point();
        segments.push_back(line_segment(current, end));
        current = end;
        break;
      }
      case 'H':
      case 'V': {
        const double value = data.number();
        Vec2 end = current;
        (upper == 'H' ? end.x() : end.y()) =
            (relative ? (upper == 'H' ? current.x() : current.y()) : 0) + value;
        segments.push_back(line_segment(current, end));
        current = end;
        break;
      }
      case 'Q': {
        const Vec2 c = origin + data.point(), end = origin + data.point();
        segments.push_back(quadratic_segment(current, c, end));
        current = end;
        break;
      }
      case 'C': {
        const Vec2 c1 = origin + data.point(), c2 = origin + data.point();
        const Vec2 end = origin + data.point();
        segments.push_back(cubic_segment(current, c1, c2, end));
        current = end;
        break;
      }
      case 'Z':
        segments.push_back(line_segment(current, start));
        current = start;
        break;
      default:
        throw PatternError(where + ": unsupported path command '" + std::string(1, command) + "'");
    }
  }
  if (segments.empty()) throw PatternError(where + ": the path has no segment");
  return segments;
}

// "fs-stack-aaron.front-part-aaron.front" -> "front".
std::string panel_name(const pugi::xml_node& path) {
  for (pugi::xml_node g = path.parent(); g; g = g.parent()) {
    const std::string id = g.attribute("id").value();
    const auto part = id.find("-part-");
    if (part == std::string::npos) continue;
    const std::string name = id.substr(part + 6);
    const auto dot = name.find_last_of('.');
    return dot == std::string::npos ? name : name.substr(dot + 1);
  }
  return path.attribute("id").value();
}

bool is_fabric(const pugi::xml_node& node) {
  const std::string classes = std::string(" ") + node.attribute("class").value() + " ";
  return std::strcmp(node.name(), "path") == 0 && classes.find(" fabric ") != std::string::npos;
}

void collect_fabric(const pugi::xml_node& node, std::vector<pugi::xml_node>& found) {
  for (pugi::xml_node child : node.children()) {
    if (std::strcmp(child.name(), "defs") == 0) continue;
    if (is_fabric(child)) found.push_back(child);
    collect_fabric(child, found);
  }
}

}  // namespace

Pattern read_freesewing_svg(const std::string& file) {
  pugi::xml_document document;
  const pugi::xml_parse_result parsed = document.load_file(file.c_str());
  if (!parsed) {
    if (parsed.status == pugi::status_file_not_found || parsed.status == pugi::status_io_error)
      throw PatternError("cannot open the pattern file '" + file + "'");
    throw PatternError(file + ": not valid XML at byte " + std::to_string(parsed.offset) + " (" +
                       parsed.description() + ")");
  }
  const pugi::xml_node svg = document.child("svg");
  if (!svg) throw PatternError(file + ": no <svg> element");
  const std::string width = svg.attribute("width").value();
  if (!width.empty() && width.find("mm") == std::string::npos &&
      width.find_first_not_of("0123456789.") != std::string::npos)
    throw PatternError(file + ": width '" + width + "' is not in mm");
  const double metres_per_unit = 1e-3;

  std::vector<pugi::xml_node> paths;
  collect_fabric(svg, paths);
  if (paths.empty()) throw PatternError(file + ": no <path class=\"fabric\"> element");
  Pattern pattern;
  pattern.name = file.substr(file.find_last_of('/') + 1);
  for (const pugi::xml_node& node : paths) {
    PanelOutline panel;
    panel.name = panel_name(node);
    const std::string where =
        file + ": path '" + node.attribute("id").value() + "' (panel '" + panel.name + "')";
    if (!node.attribute("d")) throw PatternError(where + " has no path data (d)");
    // y up, metres.
    const Mat2 flip = Vec2(metres_per_unit, -metres_per_unit).asDiagonal();
    int number = 0;
    for (const Segment& s : parse_path(node.attribute("d").value(), where)) {
      const Segment m = transformed(s, flip, Vec2::Zero());
      if (length_m({m}) < 1e-9) continue;
      panel.edges.push_back({std::to_string(++number), {m}});
    }
    if (panel.edges.size() < 2) throw PatternError(where + ": fewer than two segments");
    double twice_area = 0.0;
    for (const Edge& e : panel.edges) {
      const Vec2 a = e.segments.front().start, b = e.segments.back().end;
      twice_area += a.x() * b.y() - b.x() * a.y();
    }
    if (twice_area < 0) {  // clockwise: walk it the other way
      std::vector<Edge> ccw;
      for (auto e = panel.edges.rbegin(); e != panel.edges.rend(); ++e)
        ccw.push_back({e->name, {reversed(e->segments.front())}});
      panel.edges = ccw;
    }
    pattern.panels.push_back(panel);
  }
  return pattern;
}

}  // namespace tightfit::pattern
