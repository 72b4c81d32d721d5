// DXF patterns in the AAMA / ASTM D6673 convention (docs/patterns.md), read with dxflib: one
// BLOCK per piece (and per size in a graded file), its boundary on layer 1 as one or several
// POLYLINE, LWPOLYLINE, LINE, ARC or SPLINE entities, turn points (corners) as POINTs on layer
// 2, notches on layer 4, the grain line a LINE on layer 7, and TEXT "PIECE NAME: ..." and
// "SIZE: ..." naming it.
#pragma once

#include "pattern/pattern.h"

#include <string>
#include <vector>

namespace tightfit::pattern {

// Each block with a boundary becomes a panel named by its PIECE NAME (else the block's name).
// The boundary's entities are chained end to start (boundary_chain.h) with a tolerance of
// 1/1000 of the piece's size. It is cut into edges at the turn points (else at the joints
// between entities, else at every vertex of a single polyline), edges named "1", "2", ... from
// the first corner along the outline, which is made counter-clockwise; a vertex's bulge makes
// an arc. The grain line gives the warp direction (the weft is perpendicular).
// Sizes: the blocks whose SIZE is `options.size`, and those without a SIZE; a file of several
// sizes needs one chosen. Units: $INSUNITS (1 inch, 2 foot, 4 mm, 5 cm, 6 m); without it,
// `options.units`; without either, mm, refused when a piece would be under 2 cm or over 3 m
// across or the largest under 10 cm (the message says what each unit would make of it).
// Throws PatternError naming the file, the block and why.
Pattern read_aama_dxf(const std::string& path, const PatternFileOptions& options = {});

// The sizes of a graded file (the blocks' SIZE text, in the order first met); empty when the
// file names none.
std::vector<std::string> aama_dxf_sizes(const std::string& path);

}  // namespace tightfit::pattern
