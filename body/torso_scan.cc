#include "body/torso_scan.h"

#include "body/body_measurements.h"

#include <cmath>
#include <cstdio>
#include <limits>

namespace tightfit {

namespace {

std::string at(double z) {
  char text[48];
  std::snprintf(text, sizeof text, "z = %.3f m", z);
  return text;
}

// The side's outer extent of a loop: its largest x on the left (side 0), -x on the right.
double outer(const SectionLoop& loop, int side) {
  return side == 0 ? loop.max_m.x() : -loop.min_m.x();
}
double inner(const SectionLoop& loop, int side) {
  return side == 0 ? loop.min_m.x() : -loop.max_m.x();
}

// Whether the plane's loops show two legs apart under `above` (the torso's loop a level
// higher): a loop of at least a tenth of its area on either side of its centroid within its
// breadth (one of them may still hold the centroid, where the thighs nearly touch). Returns the
// left and right legs' loops, or -1s.
std::array<int, 2> legs_apart(const std::vector<SectionLoop>& loops, const SectionLoop& above) {
  std::array<int, 2> legs = {-1, -1};
  for (std::size_t i = 0; i < loops.size(); ++i) {
    const SectionLoop& l = loops[i];
    const double x = l.centroid_m.x();
    if (l.area_m2 < 0.1 * above.area_m2 || x < above.min_m.x() || x > above.max_m.x()) continue;
    const int side = x > above.centroid_m.x() ? 0 : 1;
    if (legs[side] < 0 || l.area_m2 > loops[legs[side]].area_m2) legs[side] = static_cast<int>(i);
  }
  if (legs[0] < 0 || legs[1] < 0) return {-1, -1};
  return legs;
}

}  // namespace

int follow_loop(const SectionCutter& cutter, const std::vector<SectionLoop>& loops,
                const Vec3& from, double reach) {
  int best = -1;
  for (std::size_t i = 0; i < loops.size(); ++i)
    if (cutter.encloses(loops[i], from) && (best < 0 || loops[i].area_m2 < loops[best].area_m2))
      best = static_cast<int>(i);
  if (best >= 0) return best;
  double nearest = reach;
  for (std::size_t i = 0; i < loops.size(); ++i) {
    const double d = cutter.distance_across(loops[i].centroid_m, from);
    if (d < nearest) {
      nearest = d;
      best = static_cast<int>(i);
    }
  }
  return best;
}

TorsoScan scan_torso(const SectionCutter& cutter) {
  TorsoScan scan;
  scan.floor_m = cutter.lowest();
  scan.top_m = cutter.highest();
  const double height = scan.height_m();
  // 800 levels: 2 mm apart on an adult, finer than any landmark's definition.
  scan.step_m = height / 800;
  for (double z = scan.top_m - scan.step_m; z > scan.floor_m + 0.5 * scan.step_m; z -= scan.step_m)
    scan.levels.push_back({z, cutter.cut(z), -1, {-1, -1}});
  std::vector<BodyLevel>& levels = scan.levels;
  const int n = static_cast<int>(levels.size());
  // Start below the crown (3 % of the height) on the largest loop: the head.
  int k = 0;
  while (k < n && levels[k].z_m > scan.top_m - 0.03 * height) ++k;
  if (k >= n || levels[k].loops.empty())
    throw BodyMeasureError("crotch: the body has no sections below its top");
  for (std::size_t i = 0; i < levels[k].loops.size(); ++i)
    if (levels[k].core < 0 || levels[k].loops[i].area_m2 > levels[k].loops[levels[k].core].area_m2)
      levels[k].core = static_cast<int>(i);
  // An arm parts from the torso where the torso's side pulls in by more than 2 % of the height
  // (3.5 cm on an adult: an arm is thicker) between two levels, the arm's loop beside it (none
  // below an arm held level). Looked for below the head (18 % of the height under the top), so an
  // ear lobe does not count.
  const double pull_in = 0.02 * height;
  const auto torso_at = [&](double z, const Vec3& from) -> const SectionLoop* {
    static thread_local std::vector<SectionLoop> loops;
    loops = cutter.cut(z);
    const int i = follow_loop(cutter, loops, from, 0.1 * height);
    return i < 0 ? nullptr : &loops[i];
  };
  for (++k; k < n; ++k) {
    BodyLevel& level = levels[k];
    const SectionLoop& above = scan.core(k - 1);
    const bool below_armpits =
        scan.armpit_level[0] >= 0 && scan.armpit_level[1] >= 0 &&
        level.z_m < std::min(scan.armpit_m[0].z(), scan.armpit_m[1].z()) - 0.02 * height;
    if (below_armpits) {
      const std::array<int, 2> legs = legs_apart(level.loops, above);
      if (legs[0] >= 0) {
        // Between this level and the one above: halve the interval ten times (0.002 mm).
        double low = level.z_m, high = levels[k - 1].z_m;
        for (int i = 0; i < 10; ++i) {
          const double mid = 0.5 * (low + high);
          (legs_apart(cutter.cut(mid), above)[0] >= 0 ? low : high) = mid;
        }
        scan.crotch_m = Vec3(above.centroid_m.x(), above.centroid_m.y(), 0.5 * (low + high));
        scan.crotch_level = k;
        level.leg = legs;
        break;
      }
    }
    level.core = follow_loop(cutter, level.loops, above.centroid_m, 0.1 * height);
    if (level.core < 0)
      throw BodyMeasureError("crotch: the torso's section cannot be followed below " +
                             at(levels[k - 1].z_m) + " (no section near its centroid)");
    const SectionLoop& here = scan.core(k);
    if (level.z_m > scan.top_m - 0.18 * height) continue;
    for (int side = 0; side < 2; ++side) {
      if (scan.armpit_level[side] >= 0 || outer(here, side) > outer(above, side) - pull_in)
        continue;
      // The arm: the loop nearest the torso whose centroid lies beyond the torso's side (on a
      // coarse mesh it may overlap the torso's breadth, in front of or behind it).
      int arm = -1;
      for (std::size_t i = 0; i < level.loops.size(); ++i) {
        const SectionLoop& l = level.loops[i];
        const double centre = side == 0 ? l.centroid_m.x() : -l.centroid_m.x();
        if (static_cast<int>(i) == level.core || centre < outer(here, side)) continue;
        if (arm < 0 || inner(l, side) < inner(level.loops[arm], side)) arm = static_cast<int>(i);
      }
      const double threshold = 0.5 * (outer(here, side) + outer(above, side));
      double low = level.z_m, high = levels[k - 1].z_m;
      for (int i = 0; i < 10; ++i) {
        const double mid = 0.5 * (low + high);
        const SectionLoop* torso = torso_at(mid, here.centroid_m);
        (torso && outer(*torso, side) < threshold ? low : high) = mid;
      }
      // The armpit: in the gap between torso and arm, at the arm's innermost point's depth; an
      // arm held level (T-pose) leaves no loop below it: then on the torso's side.
      const double sign = side == 0 ? 1.0 : -1.0;
      scan.armpit_m[side] = Vec3(sign * outer(here, side), here.centroid_m.y(), 0.5 * (low + high));
      if (arm >= 0) {
        const SectionLoop& a = level.loops[arm];
        Vec3 innermost = a.points_m.front();
        for (const Vec3& p : a.points_m)
          if ((side == 0 ? p.x() < innermost.x() : p.x() > innermost.x())) innermost = p;
        scan.armpit_m[side].x() = sign * 0.5 * (outer(here, side) + inner(a, side));
        scan.armpit_m[side].y() = innermost.y();
      }
      scan.armpit_level[side] = k;
    }
  }
  for (int side = 0; side < 2; ++side)
    if (scan.armpit_level[side] < 0)
      throw BodyMeasureError(std::string("armpit ") + (side == 0 ? "left" : "right") +
                             ": no level below the head where the arm parts from the torso (the "
                             "torso's side never pulls in by an arm's breadth): the arms must "
                             "hang apart from the torso below the armpits (A-pose or T-pose)");
  if (scan.crotch_level < 0)
    throw BodyMeasureError(
        "crotch: the sections below the armpits stay one piece down to the floor (" +
        at(scan.floor_m) + "): no two legs apart; a body needs its legs, apart below the crotch");
  // Each leg followed down to the floor.
  for (int k = scan.crotch_level + 1; k < n; ++k)
    for (int side = 0; side < 2; ++side) {
      const int previous = levels[k - 1].leg[side];
      if (previous < 0) continue;
      levels[k].leg[side] = follow_loop(cutter, levels[k].loops,
                                        levels[k - 1].loops[previous].centroid_m, 0.05 * height);
    }
  return scan;
}

}  // namespace tightfit
