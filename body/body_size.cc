#include "body/body_size.h"

#include "body/body_measurements.h"

#include <cstdio>

namespace tightfit {

namespace {

std::string metres(double x) {
  char text[64];
  std::snprintf(text, sizeof text, x >= 100 ? "%.0f m" : "%.3g m", x);
  return text;
}

constexpr const char* units_hint =
    " Is the file in other units? Say how many metres one unit is (Body/Mesh/Unit scale, or "
    "measure's --units: 0.001 for millimetres, 0.01 for centimetres).";

}  // namespace

BodyExtent body_extent(const std::vector<Vec3>& vertices) {
  BodyExtent e;
  if (vertices.empty()) return e;
  e.min_m = e.max_m = vertices.front();
  for (const Vec3& x : vertices) {
    e.min_m = e.min_m.cwiseMin(x);
    e.max_m = e.max_m.cwiseMax(x);
  }
  return e;
}

std::string describe_extent(const BodyExtent& extent) {
  const Vec3 s = extent.size_m();
  char text[160];
  std::snprintf(text, sizeof text, "%.3f m tall (z) x %.3f m wide (x) x %.3f m deep (y)", s.z(),
                s.x(), s.y());
  return text;
}

void check_body_size(const BodyExtent& extent, const std::string& what) {
  const Vec3 s = extent.size_m();
  const double largest = s.maxCoeff();
  if (largest > 4.0)
    throw BodyMeasureError(what + ": the body is " + describe_extent(extent) +
                           "; no body a garment is made for is over 4 m." + units_hint);
  if (largest < 0.01)
    throw BodyMeasureError(what + ": the body is " + describe_extent(extent) +
                           "; no body a garment is made for is under 1 cm." + units_hint);
  const double across = std::max(s.x(), s.y());
  if (across > 1.2 && across > 2 * s.z())
    throw BodyMeasureError(
        what + ": the body is " + describe_extent(extent) + ": it lies down along " +
        (s.x() > s.y() ? "x" : "y") +
        " instead of standing along z. Is the file's up axis another one? (Body/Mesh/Up axis, or "
        "measure's --up: the file's axis that points from the feet to the head)");
}

void check_standing_person(const BodyExtent& extent, const std::string& what) {
  check_body_size(extent, what);
  const Vec3 s = extent.size_m();
  if (s.z() < 0.4 || s.z() > 2.6) {
    const double across = std::max(s.x(), s.y());
    if (across > s.z())
      throw BodyMeasureError(what + ": the body is " + describe_extent(extent) +
                             ": it is longer across than it is tall, no standing person. Is the "
                             "file's up axis another one? (Body/Mesh/Up axis, or measure's --up)");
    throw BodyMeasureError(what + ": the body is " + metres(s.z()) +
                           " tall; a standing person is 0.4 to 2.6 m." + units_hint);
  }
}

}  // namespace tightfit
