// GarmentCode's JSON pattern specification (docs/patterns.md): panels of 2D vertices and
// edges between them, each edge straight or curved (quadratic, cubic, circle) relative to
// itself, the panel's 3D translation and rotation, and stitches between edges.
#pragma once

#include "pattern/pattern.h"

#include <string>

namespace tightfit::pattern {

// Reads `path`. Lengths are divided by properties.units_in_meter (default 100: cm). A panel
// listed clockwise (seen from its inside) is mirrored left to right, so every outline is
// counter-clockwise seen from outside; a stitch then joins its two edges walked in opposite
// directions. An edge is named by its label when no other edge of its panel has that label,
// else by its index ("0", "1", ...). Throws PatternError naming the file, panel or edge and
// why (malformed JSON, missing key, wrong type, a bad index, unknown curvature).
Pattern read_garmentcode_json(const std::string& path);

}  // namespace tightfit::pattern
