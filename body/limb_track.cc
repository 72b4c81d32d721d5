#include "body/limb_track.h"

#include "body/torso_scan.h"

#include <algorithm>

namespace tightfit {

namespace {

std::vector<LimbSection> follow(const TriangleSurface& surface, const Vec3& start,
                                const Vec3& direction, double step, double reach,
                                double max_radius) {
  const SectionCutter cutter(surface, direction);
  const Vec3 d = cutter.normal();
  std::vector<LimbSection> sections;
  Vec3 centre = start;
  for (double t = d.dot(start); t <= cutter.highest(); t += step) {
    const Vec3 predicted = centre + (t - d.dot(centre)) * d;
    std::vector<SectionLoop> loops = cutter.cut(t);
    const int i = follow_loop(cutter, loops, predicted, reach);
    if (i < 0) break;
    LimbSection s;
    s.t_m = t;
    s.loop = std::move(loops[i]);
    for (const Vec3& p : s.loop.points_m)
      s.reach_m = std::max(s.reach_m, (p - s.loop.centroid_m).norm());
    if (s.reach_m > max_radius) {
      centre = predicted;  // still in the torso: go on along the line
      continue;
    }
    centre = s.loop.centroid_m;
    sections.push_back(std::move(s));
  }
  return sections;
}

}  // namespace

LimbTrack follow_limb(const TriangleSurface& surface, const Vec3& start, const Vec3& direction,
                      double step, double reach, double max_radius, double fit_share) {
  LimbTrack track;
  std::vector<LimbSection> first = follow(surface, start, direction, step, reach, max_radius);
  std::vector<Vec3> centroids;
  const std::size_t n = std::max<std::size_t>(2, fit_share * first.size());
  for (std::size_t i = 0; i < std::min(n, first.size()); ++i)
    centroids.push_back(first[i].loop.centroid_m);
  if (centroids.size() < 2) {
    track.axis.point_m = start;
    track.axis.direction = direction.normalized();
    track.sections = std::move(first);
    return track;
  }
  track.axis = fit_line(centroids, direction);
  // Start again where the first pass started, on the fitted axis.
  const Vec3 d = track.axis.direction;
  const Vec3 restart = track.axis.point_m + d.dot(start - track.axis.point_m) * d;
  track.sections = follow(surface, restart, d, step, reach, max_radius);
  return track;
}

}  // namespace tightfit
