#include "body/limb_sections.h"

#include "body/body_measurements.h"
#include "body/torso_scan.h"

#include <cstdio>

namespace tightfit {

LimbSections::LimbSections(const TriangleSurface& surface, const Vec3& point_m, const Vec3& up)
    : cutter_(surface, up), point_m_(point_m) {}

std::optional<SectionLoop> LimbSections::at(double s_m) const {
  std::vector<SectionLoop> loops = cutter_.cut(s_m);
  const int i = follow_loop(cutter_, loops, axis_at(s_m), 0.05);
  if (i < 0) return std::nullopt;
  return std::move(loops[i]);
}

double LimbSections::girth_m(double s_m, const std::string& what) const {
  if (const auto loop = at(s_m)) return loop->hull_perimeter_m;
  const Vec3 p = axis_at(s_m);
  char where[160];
  std::snprintf(where, sizeof where, " at (%.4f, %.4f, %.4f) m", p.x(), p.y(), p.z());
  throw BodyMeasureError(what + ": the plane normal to the limb's axis" + where +
                         " does not cut the limb (the axis leaves it)");
}

}  // namespace tightfit
