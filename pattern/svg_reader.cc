#include "pattern/svg_reader.h"

#include <pugixml.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
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
  // An arc's large-arc or sweep flag: one character, 0 or 1, which may run into the next
  // number ("a 5,5 0 0110,0").
  bool flag() {
    skip_separators();
    if (*p_ != '0' && *p_ != '1')
      throw PatternError(where_ + ": an arc flag must be 0 or 1, not '" +
                         std::string(p_).substr(0, 10) + "'");
    return *p_++ == '1';
  }

 private:
  void skip_separators() {
    while (*p_ == ',' || std::isspace(static_cast<unsigned char>(*p_))) ++p_;
  }
  const char* p_;
  std::string where_;
};

// SVG's elliptical arc from `from` to `to` (radii rx, ry, x axis turned by phi degrees,
// flags as written), by the SVG specification's conversion to centre parameters (SVG 1.1,
// F.6.5 and F.6.6: radii too small for the chord are scaled up). A circle (equal radii) is one
// exact arc segment; an ellipse is cubic Bezier pieces of at most 90 degrees each, whose
// control points lie on the tangents at 4/3 tan(delta / 4) of the radius: a radial error under
// 3e-4 of the radius.
std::vector<Segment> svg_arc(const Vec2& from, const Vec2& to, double rx, double ry, double phi_deg,
                             bool large_arc, bool sweep) {
  rx = std::abs(rx), ry = std::abs(ry);
  if ((to - from).norm() == 0) return {};
  if (rx == 0 || ry == 0) return {line_segment(from, to)};
  const Eigen::Rotation2Dd turn(phi_deg * M_PI / 180);
  const Vec2 h = turn.inverse() * ((from - to) / 2);  // x1', y1'
  const double lambda = h.x() * h.x() / (rx * rx) + h.y() * h.y() / (ry * ry);
  if (lambda > 1) rx *= std::sqrt(lambda), ry *= std::sqrt(lambda);
  const double num = rx * rx * ry * ry - rx * rx * h.y() * h.y() - ry * ry * h.x() * h.x();
  const double den = rx * rx * h.y() * h.y() + ry * ry * h.x() * h.x();
  const double coef = (large_arc != sweep ? 1 : -1) * std::sqrt(std::max(0.0, num / den));
  const Vec2 cp = coef * Vec2(rx * h.y() / ry, -ry * h.x() / rx);
  const Vec2 centre = turn * cp + (from + to) / 2;
  const Vec2 u((h.x() - cp.x()) / rx, (h.y() - cp.y()) / ry);
  const Vec2 v((-h.x() - cp.x()) / rx, (-h.y() - cp.y()) / ry);
  const double theta1 = std::atan2(u.y(), u.x());
  double delta = std::atan2(u.x() * v.y() - u.y() * v.x(), u.dot(v));
  if (!sweep && delta > 0) delta -= 2 * M_PI;
  if (sweep && delta < 0) delta += 2 * M_PI;
  if (std::abs(rx - ry) <= 1e-12 * std::max(rx, ry))
    return {arc_segment_from_bulge(from, to, std::tan(delta / 4))};
  auto at = [&](double t) { return centre + turn * Vec2(rx * std::cos(t), ry * std::sin(t)); };
  auto tangent = [&](double t) { return turn * Vec2(-rx * std::sin(t), ry * std::cos(t)); };
  const int pieces = static_cast<int>(std::ceil(std::abs(delta) / (M_PI / 2) - 1e-9));
  const double step = delta / pieces, k = 4.0 / 3.0 * std::tan(step / 4);
  std::vector<Segment> segments;
  Vec2 start = from;
  for (int i = 0; i < pieces; ++i) {
    const double a = theta1 + i * step, b = a + step;
    const Vec2 end = i + 1 == pieces ? to : at(b);
    segments.push_back(cubic_segment(start, start + k * tangent(a), end - k * tangent(b), end));
    start = end;
  }
  return segments;
}

// The path's segments, grouped by the command that drew them (an elliptical arc is several).
std::vector<std::vector<Segment>> parse_path(const char* d, const std::string& where) {
  PathData data(d, where);
  std::vector<std::vector<Segment>> segments;
  Vec2 current = Vec2::Zero(), start = Vec2::Zero();
  char command = 0, last = 0;
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
        segments.push_back({line_segment(current, end)});
        current = end;
        break;
      }
      case 'H':
      case 'V': {
        const double value = data.number();
        Vec2 end = current;
        (upper == 'H' ? end.x() : end.y()) =
            (relative ? (upper == 'H' ? current.x() : current.y()) : 0) + value;
        segments.push_back({line_segment(current, end)});
        current = end;
        break;
      }
      case 'Q':
      case 'T': {
        // T: the control point is the previous Q's reflected through the current point.
        const Vec2 c = upper == 'Q'  ? origin + data.point()
                       : last == 'Q' ? 2 * current - segments.back().back().control1
                                     : current;
        const Vec2 end = origin + data.point();
        segments.push_back({quadratic_segment(current, c, end)});
        current = end;
        break;
      }
      case 'C':
      case 'S': {
        // S: the first control point is the previous C's second reflected.
        const Vec2 c1 = upper == 'C'  ? origin + data.point()
                        : last == 'C' ? 2 * current - segments.back().back().control2
                                      : current;
        const Vec2 c2 = origin + data.point();
        const Vec2 end = origin + data.point();
        segments.push_back({cubic_segment(current, c1, c2, end)});
        current = end;
        break;
      }
      case 'A': {
        const double rx = data.number(), ry = data.number(), phi = data.number();
        const bool large_arc = data.flag(), sweep = data.flag();
        const Vec2 end = origin + data.point();
        const std::vector<Segment> arc = svg_arc(current, end, rx, ry, phi, large_arc, sweep);
        if (!arc.empty()) segments.push_back(arc);
        current = end;
        break;
      }
      case 'Z':
        segments.push_back({line_segment(current, start)});
        current = start;
        break;
      default:
        throw PatternError(where + ": unsupported path command '" + std::string(1, command) + "'");
    }
    // The kind of curve just drawn, for a following S or T to reflect its control point.
    const Segment::Kind kind = segments.empty() ? Segment::Kind::line : segments.back().back().kind;
    last = (upper == 'Q' || upper == 'T') && kind == Segment::Kind::quadratic ? 'Q'
           : (upper == 'C' || upper == 'S') && kind == Segment::Kind::cubic   ? 'C'
                                                                              : 0;
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
    for (const std::vector<Segment>& drawn : parse_path(node.attribute("d").value(), where)) {
      std::vector<Segment> m;
      for (const Segment& s : drawn) m.push_back(transformed(s, flip, Vec2::Zero()));
      if (length_m(m) < 1e-9) continue;
      panel.edges.push_back({std::to_string(++number), m});
    }
    if (panel.edges.size() < 2) throw PatternError(where + ": fewer than two segments");
    double twice_area = 0.0;
    for (const Edge& e : panel.edges)  // sampled: an arc's bulge counts
      for (const Segment& seg : e.segments)
        for (int k = 0; k < 8; ++k) {
          const Vec2 a = point_at(seg, k / 8.0), b = point_at(seg, (k + 1) / 8.0);
          twice_area += a.x() * b.y() - b.x() * a.y();
        }
    if (twice_area < 0) {  // clockwise: walk it the other way
      std::vector<Edge> ccw;
      for (auto e = panel.edges.rbegin(); e != panel.edges.rend(); ++e) {
        Edge r{e->name, {}};
        for (auto s = e->segments.rbegin(); s != e->segments.rend(); ++s)
          r.segments.push_back(reversed(*s));
        ccw.push_back(r);
      }
      panel.edges = ccw;
    }
    pattern.panels.push_back(panel);
  }
  return pattern;
}

}  // namespace tightfit::pattern
