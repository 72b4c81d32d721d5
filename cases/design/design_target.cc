#include "cases/design/design_target.h"

#include "cases/compression_class.h"
#include "core/plain_text.h"

#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace tightfit {

namespace {

const NamedValue* find(const std::vector<NamedValue>& list, const std::string& name) {
  for (const NamedValue& v : list)
    if (v.name == name) return &v;
  return nullptr;
}

std::string number_text(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", x);
  return text;
}

}  // namespace

std::vector<NamedValue> parse_named_values(const std::string& text, const std::string& entry) {
  std::vector<NamedValue> values;
  std::size_t begin = 0;
  while (begin < text.size()) {
    const std::size_t comma = std::min(text.find(',', begin), text.size());
    const std::string piece = trimmed(text.substr(begin, comma - begin));
    begin = comma + 1;
    if (piece.empty()) continue;
    const std::size_t colon = piece.find(':');
    const std::string name = trimmed(piece.substr(0, colon));
    const std::string number = colon == std::string::npos ? "" : trimmed(piece.substr(colon + 1));
    char* end = nullptr;
    const double x = std::strtod(number.c_str(), &end);
    if (name.empty() || number.empty() || end != number.c_str() + number.size() ||
        !std::isfinite(x))
      throw std::invalid_argument(entry + ": cannot read '" + piece +
                                  "'; expected NAME:NUMBER (e.g. B:0.02)");
    if (find(values, name))
      throw std::invalid_argument(entry + ": point " + name + " is given twice");
    values.push_back({name, x});
  }
  if (values.empty()) throw std::invalid_argument(entry + ": no NAME:NUMBER given");
  return values;
}

std::vector<NamedValue> parse_design_points(const std::string& text, const std::string& entry) {
  std::vector<NamedValue> points;
  std::size_t begin = 0;
  while (begin < text.size()) {
    const std::size_t comma = std::min(text.find(',', begin), text.size());
    std::string piece = trimmed(text.substr(begin, comma - begin));
    begin = comma + 1;
    if (piece.empty()) continue;
    if (piece.find(':') == std::string::npos) {
      // A bare name: its height from the body's landmarks.
      if (piece.find_first_of(" \t") != std::string::npos)
        throw std::invalid_argument(entry + ": cannot read '" + piece +
                                    "'; expected NAME or NAME:HEIGHT (e.g. B or B:0.02)");
      if (find(points, piece))
        throw std::invalid_argument(entry + ": point " + piece + " is given twice");
      points.push_back({piece, std::nan("")});
      continue;
    }
    for (const NamedValue& v : parse_named_values(piece, entry)) {
      if (find(points, v.name))
        throw std::invalid_argument(entry + ": point " + v.name + " is given twice");
      points.push_back(v);
    }
  }
  if (points.empty()) throw std::invalid_argument(entry + ": no point given");
  return points;
}

std::vector<NamedValue> design_point_heights(const std::vector<NamedValue>& stated, double length_m,
                                             const std::vector<NamedValue>& landmark_heights) {
  std::vector<NamedValue> stated_heights = stated;
  for (NamedValue& p : stated_heights) {
    if (!std::isnan(p.value)) continue;
    const NamedValue* found = find(landmark_heights, p.name);
    if (!found)
      throw std::invalid_argument(
          "Points: " + p.name + " has no height, and " +
          (landmark_heights.empty()
               ? std::string("the case's garment is not cut to the body's landmarks")
               : "the body's landmarks give no point " + p.name + " on the garment") +
          ": give its height along the garment (" + p.name + ":HEIGHT, m)");
    p.value = found->value;
  }
  for (std::size_t k = 0; k < stated_heights.size(); ++k) {
    const NamedValue& p = stated_heights[k];
    if (!(p.value >= 0 && p.value <= length_m))
      throw std::invalid_argument("Points: " + p.name + " at " + number_text(p.value) +
                                  " m lies outside the garment (0 to " + number_text(length_m) +
                                  " m along it)");
    if (k > 0 && !(p.value > stated_heights[k - 1].value))
      throw std::invalid_argument("Points: " + p.name + " must lie above " +
                                  stated_heights[k - 1].name +
                                  " (the heights must increase up the limb)");
  }
  return stated_heights;
}

std::vector<double> target_pressures_mmHg(const std::vector<NamedValue>& points,
                                          const DesignTarget& target) {
  const bool by_class = target.kind == DesignTarget::Kind::compression_class;
  const std::vector<NamedValue>& given = by_class ? target.profile : target.pressures;
  const std::string entry = by_class ? "Profile" : "Pressures";
  for (const NamedValue& v : given)
    if (!find(points, v.name))
      throw std::invalid_argument(entry + ": " + v.name + " is not one of the design's Points");
  double at_b = 0.0;
  if (by_class) {
    const CompressionClassRange range = ral_gz_387_range(target.class_number);
    at_b = target.pressure_at_b_mmHg;
    if (at_b == 0.0) {
      if (std::isinf(range.high_mmHg))
        throw std::invalid_argument(
            "Pressure at B: class IV has no upper bound; state the "
            "pressure wanted at B (49 mmHg or more)");
      at_b = 0.5 * (range.low_mmHg + range.high_mmHg);
    }
    if (!(at_b >= range.low_mmHg && at_b <= range.high_mmHg))
      throw std::invalid_argument("Pressure at B: " + number_text(at_b) +
                                  " mmHg lies outside the class's range (" +
                                  ral_gz_387_class(range.low_mmHg).text + ")");
    const NamedValue* b = find(given, "B");
    if (!b || std::abs(b->value - 1.0) > 1e-12)
      throw std::invalid_argument("Profile: the share at B must be 1 (the class is B's pressure)");
  }
  std::vector<double> targets;
  for (const NamedValue& p : points) {
    const NamedValue* v = find(given, p.name);
    if (!v) throw std::invalid_argument(entry + ": no value for point " + p.name);
    if (!(v->value > 0))
      throw std::invalid_argument(entry + ": the value at " + p.name + " must be positive");
    if (by_class && !targets.empty() && v->value * at_b > targets.back() + 1e-12)
      throw std::invalid_argument("Profile: the share at " + p.name +
                                  " rises above the one below it: not degressive");
    targets.push_back(by_class ? v->value * at_b : v->value);
  }
  return targets;
}

}  // namespace tightfit
