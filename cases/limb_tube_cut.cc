#include "cases/limb_tube_cut.h"

#include "body/leg_measuring_points.h"
#include "body/limb_sections.h"
#include "core/closest_names.h"
#include "core/number_text.h"
#include "core/plain_text.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tightfit {

namespace {

bool is_point_name(const std::string& name) {
  const auto& names = leg_point_names();
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::string point_names_joined() {
  std::string joined;
  for (const std::string& n : leg_point_names()) joined += (joined.empty() ? "" : ", ") + n;
  return joined;
}

double axial_of(const std::vector<PointValue>& points, const std::string& name,
                const std::string& entry) {
  for (const PointValue& p : points)
    if (p.point == name) return p.value;
  throw std::invalid_argument(entry + ": the measuring point " + name +
                              " is not found on this limb");
}

}  // namespace

LimbTubeEnd parse_limb_tube_end(const std::string& text, const std::string& entry) {
  const std::string t = trimmed(text);
  const auto sign = t.find_first_of("+-");
  LimbTubeEnd end;
  end.point = trimmed(t.substr(0, sign));
  if (!is_point_name(end.point))
    throw std::invalid_argument(entry + " = '" + text + "': '" + end.point +
                                "' is not a measuring point (" + point_names_joined() +
                                "); expected POINT [+|- METRES], e.g. 'B - 0.02'" +
                                did_you_mean(end.point, leg_point_names(), 0));
  if (sign != std::string::npos) {
    const std::optional<double> offset = whole_number(trimmed(t.substr(sign + 1)));
    if (!offset || *offset < 0)
      throw std::invalid_argument(entry + " = '" + text +
                                  "': expected POINT [+|- METRES] with a "
                                  "non-negative distance after the sign, e.g. 'G + 0.04'");
    end.offset_m = t[sign] == '-' ? -*offset : *offset;
  }
  return end;
}

std::vector<PointValue> parse_point_values(const std::string& text, const std::string& entry) {
  std::vector<PointValue> values;
  if (trimmed(text).empty()) return values;
  for (std::size_t begin = 0; begin <= text.size();) {
    const std::size_t end = std::min(text.find(',', begin), text.size());
    const std::string piece = trimmed(text.substr(begin, end - begin));
    begin = end + 1;
    const auto colon = piece.find(':');
    const std::string name = trimmed(piece.substr(0, colon));
    const std::optional<double> value =
        colon == std::string::npos ? std::nullopt : whole_number(trimmed(piece.substr(colon + 1)));
    if (!is_point_name(name) || !value)
      throw std::invalid_argument(entry + ": '" + piece + "' is not POINT: VALUE with a point of " +
                                  point_names_joined() + " (e.g. 'B: 0.25')");
    for (const PointValue& p : values)
      if (p.point == name) throw std::invalid_argument(entry + ": point " + name + " given twice");
    values.push_back({name, *value});
  }
  return values;
}

LimbTubeSpec parse_limb_tube_spec(const std::string& limb, const std::string& from,
                                  const std::string& to, double girth_step_m,
                                  const std::string& negative_ease) {
  LimbTubeSpec spec;
  if (limb != "leg left" && limb != "leg right")
    throw std::invalid_argument("Limb = '" + limb + "': expected 'leg left' or 'leg right'" +
                                did_you_mean(limb, {"leg left", "leg right"}, 0));
  spec.side = limb == "leg left" ? 0 : 1;
  spec.from = parse_limb_tube_end(from, "From");
  spec.to = parse_limb_tube_end(to, "To");
  if (!(girth_step_m > 0)) throw std::invalid_argument("Girth step must be positive (m)");
  spec.girth_step_m = girth_step_m;
  spec.negative_ease = parse_point_values(negative_ease, "Negative ease");
  return spec;
}

double LimbTubeCut::height_of(const std::string& point) const {
  for (const PointValue& p : points)
    if (p.point == point) return p.value;
  throw std::invalid_argument("the measuring point " + point + " does not lie on the tube");
}

LimbTubeCut cut_tube_along_axis(const TriangleSurface& surface, const Vec3& axis_point_m,
                                const Vec3& up, const std::vector<PointValue>& axial_points,
                                const LimbTubeSpec& spec) {
  const LimbSections sections(surface, axis_point_m, up);
  const double s0 = axial_of(axial_points, spec.from.point, "From") + spec.from.offset_m;
  const double s1 = axial_of(axial_points, spec.to.point, "To") + spec.to.offset_m;
  if (!(s1 - s0 > 0.01))
    throw std::invalid_argument("From and To: the tube from " + spec.from.point + " to " +
                                spec.to.point + " would be " + std::to_string(100 * (s1 - s0)) +
                                " cm long; To must lie at least 1 cm above From");
  LimbTubeCut cut;
  cut.up = sections.up();
  cut.bottom_m = sections.axis_at(s0);
  cut.length_m = s1 - s0;
  // Heights along the tube: the points within it, the ends, and every step between.
  for (const PointValue& p : axial_points)
    if (p.value - s0 >= 0 && p.value - s0 <= cut.length_m)
      cut.points.push_back({p.point, p.value - s0});
  std::vector<double> heights = {0.0, cut.length_m};
  for (const PointValue& p : cut.points) heights.push_back(p.value);
  for (double h = spec.girth_step_m; h < cut.length_m; h += spec.girth_step_m) {
    const bool near_other = std::any_of(heights.begin(), heights.end(),
                                        [&](double k) { return std::abs(k - h) < 0.005; });
    if (!near_other) heights.push_back(h);
  }
  std::sort(heights.begin(), heights.end());
  heights.erase(std::unique(heights.begin(), heights.end(),
                            [](double a, double b) { return std::abs(a - b) < 1e-9; }),
                heights.end());
  std::vector<PiecewiseLinear::Point> girths;
  for (double h : heights)
    girths.push_back(
        {h, sections.girth_m(s0 + h, "the tube's girth at " + std::to_string(100 * h) + " cm")});
  cut.girths_m = PiecewiseLinear(girths, "the limb's girths");
  std::vector<PiecewiseLinear::Point> ease;
  for (const PointValue& e : spec.negative_ease) {
    const double h = axial_of(axial_points, e.point, "Negative ease") - s0;
    if (h < 0 || h > cut.length_m)
      throw std::invalid_argument("Negative ease: the point " + e.point +
                                  " lies outside the tube (From to To)");
    if (!(e.value > -1 && e.value < 1))
      throw std::invalid_argument("Negative ease: " + e.point + ": " + std::to_string(e.value) +
                                  " lies outside (-1, 1)");
    ease.push_back({h, e.value});
  }
  std::sort(ease.begin(), ease.end(),
            [](const auto& a, const auto& b) { return a.height_m < b.height_m; });
  if (!ease.empty()) cut.negative_ease = PiecewiseLinear(ease, "Negative ease");
  return cut;
}

LegLine leg_line(const TriangleSurface& surface, const BodyMeasurements& body, int side,
                 const std::string& low, const std::string& high) {
  const std::vector<LegPoint> points = leg_measuring_points(surface, body, side);
  const PartFrame& leg = body.part(side == 0 ? "leg left" : "leg right");
  // The line through the centroids of the leg's sections (normal to the leg's axis) at the two
  // points. The leg's own axis fits the whole leg from the ankle to the crotch and can pass a
  // centimetre or more from the ankle's centre.
  const LimbSections leg_sections(surface, leg.origin_m, -leg.along);
  const auto centroid = [&](const std::string& name, const char* entry) {
    for (const LegPoint& p : points)
      if (p.name == name) {
        if (const auto loop = leg_sections.at(p.axial_m)) return loop->centroid_m;
        throw BodyMeasureError(std::string(entry) + ": the leg's section at " + name +
                               " is not found");
      }
    throw std::invalid_argument(std::string(entry) + ": the measuring point " + name +
                                " is not found on this leg");
  };
  LegLine line;
  line.point_m = centroid(low, "From");
  Vec3 up = centroid(high, "To") - line.point_m;
  if (low == high || !(up.norm() > 0.01)) up = -leg.along;
  up.normalize();
  if (up.dot(-leg.along) < 0) up = -up;
  line.up = up;
  for (const LegPoint& p : points)
    line.axial.push_back({p.name, up.dot(leg_sections.axis_at(p.axial_m))});
  return line;
}

double LegLine::axial_at(const LimbTubeEnd& end, const std::string& entry) const {
  return axial_of(axial, end.point, entry) + end.offset_m;
}

LimbTubeCut cut_tube_to_leg(const TriangleSurface& surface, const BodyMeasurements& body,
                            const LimbTubeSpec& spec) {
  const LegLine line = leg_line(surface, body, spec.side, spec.from.point, spec.to.point);
  return cut_tube_along_axis(surface, line.point_m, line.up, line.axial, spec);
}

}  // namespace tightfit
