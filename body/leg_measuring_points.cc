#include "body/leg_measuring_points.h"

#include "body/limb_sections.h"

#include <algorithm>

namespace tightfit {

const std::vector<std::string>& leg_point_names() {
  static const std::vector<std::string> names = {"B", "B1", "C", "D", "E", "F", "G"};
  return names;
}

std::vector<LegPoint> leg_measuring_points(const TriangleSurface& surface,
                                           const BodyMeasurements& body, int side) {
  const std::string s = side == 0 ? " left" : " right";
  const PartFrame& leg = body.part("leg" + s);
  const LimbSections sections(surface, leg.origin_m, -leg.along);
  const auto axial = [&](const std::string& landmark) {
    return sections.axial(body.landmark(landmark + s).point_m);
  };
  const double b = axial("B"), c = axial("C"), e = axial("knee"), g = axial("G");
  constexpr double step = 0.005;  // the girths sampled every 5 mm
  // B1: the steepest rise of the girth from 1 cm above B to 2 cm below C (central differences
  // over 2 cm).
  double b1 = 0.0, steepest = -1e9;
  for (double h = b + 0.02; h <= c - 0.03; h += step) {
    const double slope =
        (sections.girth_m(h + 0.01, "B1" + s) - sections.girth_m(h - 0.01, "B1" + s)) / 0.02;
    if (slope > steepest) steepest = slope, b1 = h;
  }
  if (steepest < -1e8) b1 = 0.5 * (b + c);  // B and C closer than 5 cm: half way
  // D: the smallest girth between C and 1 cm below E.
  double d = 0.5 * (c + e), narrowest = 1e9;
  for (double h = c + step; h <= e - 0.01; h += step) {
    const double girth = sections.girth_m(h, "D" + s);
    if (girth < narrowest) narrowest = girth, d = h;
  }
  const double f = 0.5 * (e + g);
  std::vector<LegPoint> points;
  const std::vector<double> at = {b, b1, c, d, e, f, g};
  for (std::size_t k = 0; k < at.size(); ++k)
    points.push_back(
        {leg_point_names()[k], at[k], sections.girth_m(at[k], leg_point_names()[k] + s)});
  return points;
}

}  // namespace tightfit
