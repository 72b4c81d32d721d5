// SVG outlines as FreeSewing exports them (docs/patterns.md): one <path class="fabric"> per
// piece, of lines and cubic Bezier curves, in mm.
#pragma once

#include "pattern/pattern.h"

#include <string>

namespace tightfit::pattern {

// Reads every path whose class contains "fabric". The panel is named after the part of the
// group holding it ("fs-stack-aaron.front-part-aaron.front" gives "front"), else after the
// path's id. Each segment of the path's data (M, L, H, V, C, Q, Z, absolute or relative) is
// an edge named by its number along the path ("1", "2", ...), zero-length segments skipped.
// SVG's y axis points down: outlines are flipped to y up and made counter-clockwise. Units:
// the document's width attribute in mm (FreeSewing's) or, without one, user units taken as
// mm. Seams, folds and mirrored copies are not in the file: the case file names them.
// Throws PatternError naming the file, the path and why.
Pattern read_freesewing_svg(const std::string& path);

}  // namespace tightfit::pattern
