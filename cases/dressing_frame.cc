#include "cases/dressing_frame.h"

#include "cases/scenario.h"
#include "cases/scenario_landmarks.h"
#include "core/closest_names.h"
#include "core/number_text.h"
#include "core/plain_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace tightfit {

namespace {

const char* const torso_word = "torso";

bool known(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& n : names) text += (text.empty() ? "" : ", ") + n;
  return text;
}

// The unit direction `v` made normal to the unit `axis`.
Vec3 normal_to(const Vec3& v, const Vec3& axis) {
  return (v - v.dot(axis) * axis).normalized();
}

// Height of `line` along the axis from the centre, m.
double line_level_m(const BodyMeasurements& body, const std::string& line, const Vec3& centre,
                    const Vec3& axis) {
  const auto level = [&](const Vec3& p) { return (p - centre).dot(axis); };
  if (line == "armpit")
    return std::min(level(body.landmark("armpit left").point_m),
                    level(body.landmark("armpit right").point_m));
  if (line == "crotch" || line == "neck base") return level(body.landmark(line).point_m);
  return level(body.girth(line).centre_m);
}

// The torso section's largest distance from the axis along the unit `direction` (normal to the
// axis) at the girth line `line`, m: the tape's path (the section's convex hull) read across.
double reach_m(const BodyMeasurements& body, const std::string& line, const Vec3& centre,
               const Vec3& direction) {
  double reach = 0.0;
  for (const Vec3& q : body.girth(line).hull_m)
    reach = std::max(reach, std::abs((q - centre).dot(direction)));
  return reach;
}

std::string line_offset_text(const LineOffset& l) {
  char text[64];
  if (l.line.empty())
    std::snprintf(text, sizeof text, "%.4g m", l.offset_m);
  else
    std::snprintf(text, sizeof text, "%s %c %.4g m", l.line.c_str(), l.offset_m < 0 ? '-' : '+',
                  std::abs(l.offset_m));
  return text;
}

}  // namespace

const std::vector<std::string>& torso_line_names() {
  static const std::vector<std::string> names = {"crotch", "hips",   "waist",    "under-bust",
                                                 "bust",   "armpit", "neck base"};
  return names;
}

const std::vector<std::string>& torso_girth_line_names() {
  static const std::vector<std::string> names = {"hips", "waist", "under-bust", "bust"};
  return names;
}

LineOffset parse_line_offset(const std::string& text, const std::string& entry,
                             const std::vector<std::string>& lines) {
  const std::string t = trimmed(text);
  if (const std::optional<double> number = whole_number(t)) return LineOffset{"", *number};
  // The line's name is all before the last sign that follows a blank ("under-bust - 0.02").
  std::size_t sign = std::string::npos;
  for (std::size_t k = t.size(); k-- > 1;)
    if ((t[k] == '+' || t[k] == '-') && t[k - 1] == ' ') {
      sign = k;
      break;
    }
  LineOffset result;
  result.line = trimmed(t.substr(0, sign));
  const std::string expected = "; expected METRES or LINE [+|- METRES] with LINE one of " +
                               joined(lines) + ", e.g. '" + lines.back() + " - 0.02'";
  if (!known(lines, result.line))
    throw std::invalid_argument(entry + " = '" + text + "': '" + result.line +
                                "' is not a line of the torso" + expected +
                                did_you_mean(result.line, lines, 0));
  if (sign != std::string::npos) {
    const std::optional<double> offset = whole_number(trimmed(t.substr(sign + 1)));
    if (!offset || *offset < 0)
      throw std::invalid_argument(entry + " = '" + text +
                                  "': the distance after the sign is no non-negative number of "
                                  "metres" +
                                  expected);
    result.offset_m = t[sign] == '-' ? -*offset : *offset;
  }
  return result;
}

std::optional<Vec3> parse_torso_or_vector(const std::string& text, const std::string& entry) {
  const std::string t = trimmed(text);
  if (t == torso_word) return std::nullopt;
  std::vector<double> numbers;
  std::size_t start = 0;
  while (start <= t.size()) {
    const std::size_t comma = std::min(t.find(',', start), t.size());
    if (const std::optional<double> n = whole_number(trimmed(t.substr(start, comma - start))))
      numbers.push_back(*n);
    else
      numbers.push_back(std::nan(""));
    start = comma + 1;
  }
  if (numbers.size() != 3 ||
      std::any_of(numbers.begin(), numbers.end(), [](double n) { return std::isnan(n); })) {
    const std::string word = t.substr(0, t.find(','));
    throw std::invalid_argument(entry + " = '" + text +
                                "': expected 'torso' (the torso's own, from the body's "
                                "landmarks) or three numbers x,y,z" +
                                did_you_mean(word, {torso_word}, 0));
  }
  return Vec3(numbers[0], numbers[1], numbers[2]);
}

bool DressingFrameSpec::needs_landmarks() const {
  return !centre || (!axis && !axis_vertical) || !front || !semi_axis_side.line.empty() ||
         !semi_axis_front.line.empty() || !hem_height.line.empty();
}

DressingFrameSpec parse_dressing_frame(const std::string& centre, const std::string& axis,
                                       const std::string& front, const std::string& semi_side,
                                       const std::string& semi_front, const std::string& hem) {
  DressingFrameSpec spec;
  const std::string at = std::string(torso_word) + " at ";
  if (trimmed(centre).rfind(at, 0) == 0) {
    spec.centre_line = trimmed(trimmed(centre).substr(at.size()));
    if (!known(torso_line_names(), spec.centre_line))
      throw std::invalid_argument("Centre = '" + centre + "': '" + spec.centre_line +
                                  "' is not a line of the torso (" + joined(torso_line_names()) +
                                  ")" + did_you_mean(spec.centre_line, torso_line_names(), 0));
  } else {
    spec.centre = parse_torso_or_vector(centre, "Centre");
  }
  spec.axis_vertical = trimmed(axis) == "vertical";
  if (!spec.axis_vertical) spec.axis = parse_torso_or_vector(axis, "Axis");
  spec.front = parse_torso_or_vector(front, "Front");
  if (spec.axis && !(spec.axis->norm() > 0)) throw std::invalid_argument("Axis must not be zero");
  if (spec.front && !(spec.front->norm() > 0))
    throw std::invalid_argument("Front must not be zero");
  spec.semi_axis_side = parse_line_offset(semi_side, "Semi-axis side", torso_girth_line_names());
  spec.semi_axis_front = parse_line_offset(semi_front, "Semi-axis front", torso_girth_line_names());
  if (spec.semi_axis_side.line.empty() && !(spec.semi_axis_side.offset_m > 0))
    throw std::invalid_argument("Semi-axis side must be positive (m)");
  if (spec.semi_axis_front.line.empty() && !(spec.semi_axis_front.offset_m > 0))
    throw std::invalid_argument("Semi-axis front must be positive (m)");
  spec.hem_height = parse_line_offset(hem, "Hem height", torso_line_names());
  return spec;
}

PanelWrap resolve_dressing_frame(const DressingFrameSpec& spec, const BodyMeasurements* body,
                                 double start_scale) {
  if (spec.needs_landmarks() && !body)
    throw std::invalid_argument("the frame needs the body's landmarks, and there are none");
  const PartFrame* torso = body ? &body->part("torso") : nullptr;
  PanelWrap wrap;
  wrap.axis = spec.axis            ? spec.axis->normalized()
              : spec.axis_vertical ? Vec3::UnitZ()
                                   : torso->along;
  wrap.centre_m = spec.centre ? *spec.centre : torso->origin_m;
  if (!spec.centre_line.empty())  // where the torso's axis reaches the line's height along it
    wrap.centre_m +=
        torso->along * line_level_m(*body, spec.centre_line, torso->origin_m, torso->along);
  const Vec3 front = spec.front ? *spec.front : torso->front;
  if (!(std::abs(front.normalized().dot(wrap.axis)) < 1 - 1e-9))
    throw std::invalid_argument("Front lies along the Axis: it must point across it");
  wrap.front = normal_to(front, wrap.axis);
  const Vec3 side = wrap.axis.cross(wrap.front);
  const auto semi_axis = [&](const LineOffset& l, const Vec3& direction, const char* entry) {
    if (l.line.empty()) return l.offset_m;
    double semi = 0.0;
    try {
      semi = start_scale * reach_m(*body, l.line, wrap.centre_m, direction) + l.offset_m;
    } catch (const std::out_of_range& e) {
      throw std::invalid_argument(std::string(entry) + " = " + line_offset_text(l) + ": " +
                                  e.what());
    }
    if (!(semi > 0))
      throw std::invalid_argument(std::string(entry) + " = " + line_offset_text(l) + " comes to " +
                                  std::to_string(semi) + " m: it must be positive");
    return semi;
  };
  wrap.semi_axis_side_m = semi_axis(spec.semi_axis_side, side, "Semi-axis side");
  wrap.semi_axis_front_m = semi_axis(spec.semi_axis_front, wrap.front, "Semi-axis front");
  wrap.hem_height_m = spec.hem_height.offset_m;
  if (!spec.hem_height.line.empty()) try {
      wrap.hem_height_m += line_level_m(*body, spec.hem_height.line, wrap.centre_m, wrap.axis);
    } catch (const std::out_of_range& e) {
      throw std::invalid_argument("Hem height = " + line_offset_text(spec.hem_height) + ": " +
                                  e.what());
    }
  return wrap;
}

PanelWrap dressing_frame_on_body(const DressingFrameSpec& spec, const Scenario& scenario,
                                 double start_scale) {
  std::optional<BodyMeasurements> body;
  if (spec.needs_landmarks()) try {
      body = measure_body(scenario_body_surface(*scenario.body));
    } catch (const BodyMeasureError& e) {
      throw BodyMeasureError(std::string("the frame (Centre, Axis, Front, Semi-axis side, "
                                         "Semi-axis front, Hem height) needs the body's "
                                         "landmarks; give each as numbers for a body without "
                                         "them: ") +
                             e.what());
    }
  return resolve_dressing_frame(spec, body ? &*body : nullptr, start_scale);
}

std::string describe_dressing_frame(const DressingFrameSpec& spec, const PanelWrap& wrap) {
  const std::string where = spec.centre ? ""
                            : spec.centre_line.empty()
                                ? " (the torso's)"
                                : " (the torso's at the " + spec.centre_line + ")";
  char text[512];
  std::snprintf(text, sizeof text,
                "round the axis (%.4f, %.4f, %.4f)%s through (%.4f, %.4f, %.4f) m%s, front (%.4f, "
                "%.4f, %.4f); semi-axes %.4f m (side: %s) and %.4f m (front: %s); hem %.4f m "
                "along the axis from the centre (%s)",
                wrap.axis.x(), wrap.axis.y(), wrap.axis.z(),
                spec.axis            ? ""
                : spec.axis_vertical ? " (vertical)"
                                     : " (the torso's)",
                wrap.centre_m.x(), wrap.centre_m.y(), wrap.centre_m.z(), where.c_str(),
                wrap.front.x(), wrap.front.y(), wrap.front.z(), wrap.semi_axis_side_m,
                line_offset_text(spec.semi_axis_side).c_str(), wrap.semi_axis_front_m,
                line_offset_text(spec.semi_axis_front).c_str(), wrap.hem_height_m,
                line_offset_text(spec.hem_height).c_str());
  return text;
}

}  // namespace tightfit
