// The body followed down in horizontal sections (docs/measuring-bodies.md): from the
// head, the loop round the body's middle is followed level by level; where the arms part from
// it (its side pulls in by more than an arm's breadth) are the armpits, where it parts into two
// loops either side of its centroid is the crotch, and below, each leg is followed to the
// floor.
#pragma once

#include "body/section_cutter.h"

#include <array>
#include <vector>

namespace tightfit {

struct BodyLevel {
  double z_m = 0.0;
  std::vector<SectionLoop> loops;
  int core = -1;                      // the loop of the head, neck or torso (above the crotch)
  std::array<int, 2> leg = {-1, -1};  // the legs' loops (below the crotch): left, right
};

struct TorsoScan {
  double floor_m = 0.0, top_m = 0.0, step_m = 0.0;
  std::vector<BodyLevel> levels;               // from the top down, step_m apart
  std::array<Vec3, 2> armpit_m;                // left (+x), right
  std::array<int, 2> armpit_level = {-1, -1};  // the first level below each armpit
  Vec3 crotch_m = Vec3::Zero();
  int crotch_level = -1;  // the first level where the legs are apart

  double height_m() const { return top_m - floor_m; }
  const SectionLoop& core(int k) const { return levels[k].loops[levels[k].core]; }
  const SectionLoop& leg(int side, int k) const { return levels[k].loops[levels[k].leg[side]]; }
};

// Throws BodyMeasureError naming the landmark (armpit left/right, crotch) that is not found
// and why.
TorsoScan scan_torso(const SectionCutter& horizontal);

// The loop of `loops` that encloses `from` (projected onto the plane), else the one whose
// centroid lies nearest to it across the plane, if within `reach_m`; -1 if none.
int follow_loop(const SectionCutter& cutter, const std::vector<SectionLoop>& loops,
                const Vec3& from_m, double reach_m);

}  // namespace tightfit
