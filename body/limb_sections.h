// A limb cut by planes normal to its axis (docs/stocking.md, "Cut to the leg"): at each height
// along the axis, the section round the axis (not the other leg's, not the torso's), and its
// girth as a tape reads it (the section's convex hull, ISO 8559-1).
#pragma once

#include "body/section_cutter.h"

#include <optional>

namespace tightfit {

class LimbSections {
 public:
  // The axis through `point_m` along `up` (need not be unit length; turned into one).
  LimbSections(const TriangleSurface& surface, const Vec3& point_m, const Vec3& up);

  const Vec3& up() const { return cutter_.normal(); }
  // The axial coordinate of a point: up . x, m.
  double axial(const Vec3& x_m) const { return up().dot(x_m); }
  // The axis's point at axial coordinate s.
  Vec3 axis_at(double s_m) const { return point_m_ + (s_m - axial(point_m_)) * up(); }

  // The section at axial coordinate s round the axis (the loop enclosing the axis's point, else
  // the one whose centroid lies within 5 cm of it), if the plane meets the limb there.
  std::optional<SectionLoop> at(double s_m) const;
  // Its tape girth (m). Throws BodyMeasureError naming `what` and the height when the plane
  // misses the limb.
  double girth_m(double s_m, const std::string& what) const;

 private:
  SectionCutter cutter_;
  Vec3 point_m_;
};

}  // namespace tightfit
