// The panels' own triangles of a welded simulation mesh: the finite-element mesh is built on
// the pattern, where a seam is two edges (one per panel), not one.
#pragma once

#include "core/garment.h"

#include <vector>

namespace tightfit {

// Each triangle of `mesh` with its corners as unwelded vertex indices: each corner is the copy
// of its welded vertex inside the triangle's panel; where a panel holds two copies (a
// one-panel tube), the copies whose layout edge lengths match the rest triangle win.
std::vector<Triangle> unwelded_triangles(const SimulationMesh& mesh);

}  // namespace tightfit
