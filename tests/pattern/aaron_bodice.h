// FreeSewing's aaron (a tank top) as a bodice: front and back cut on the fold, sewn at the
// sides and shoulders. Shared by the bodice test and the pattern benchmark.
#pragma once

#include "pattern/pattern_file.h"

#include <string>

namespace tightfit::pattern {

// aaron's edges along each path: 1 fold, 2 hem, 3 side, 4 armhole, 5 shoulder, 6 neck.
// Both pieces are counter-clockwise seen from outside: a seam joins a front edge with the
// back's mirror image of it, walked the other way (the hems meet at the sides, the necks at
// the shoulders).
inline Pattern aaron_bodice(const std::string& patterns_dir) {
  Pattern p = read_pattern_file(patterns_dir + "/freesewing_aaron_cisFemaleAdult34_outline.svg");
  p.panels.resize(2);  // front and back; not the bindings
  p.panels[0].fold_edge = "1";
  p.panels[1].fold_edge = "1";
  p.seams = parse_seam_list(
      "front:3 -- back:3 mirrored reversed; front:3 mirrored -- back:3 reversed;"
      "front:5 -- back:5 mirrored reversed; front:5 mirrored -- back:5 reversed");
  return p;
}

}  // namespace tightfit::pattern
