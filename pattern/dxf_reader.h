// DXF patterns in the AAMA / ASTM D6673 convention (docs/patterns.md), read with dxflib: one
// BLOCK per piece, its boundary a POLYLINE on layer 1, turn points (corners) as POINTs on
// layer 2, curve points on layer 3, notches on layer 4, the grain line a LINE on layer 7, and
// TEXT "PIECE NAME: ..." naming it.
#pragma once

#include "pattern/pattern.h"

#include <string>

namespace tightfit::pattern {

// Each block with a boundary becomes a panel named by its PIECE NAME (else the block's name).
// The boundary is cut into edges at the turn points (every vertex when the block has none),
// edges named "1", "2", ... from the first turn point along the outline, which is made
// counter-clockwise; a vertex's bulge makes an arc. The grain line gives the warp direction
// (the weft is perpendicular). Units: $INSUNITS (4 mm, 5 cm, 6 m, 1 inch), mm when absent.
// Throws PatternError naming the file, the block and why (no such file, no piece, an
// unfinished or open boundary, a turn point off the boundary).
Pattern read_aama_dxf(const std::string& path);

}  // namespace tightfit::pattern
