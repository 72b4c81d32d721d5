// A garment's state carried from one mesh of its pattern to another (a coarse mesh dressed
// cheaply, then the case's fine mesh settled from it; docs/dressing.md "Coarse to fine").
// Both meshes are cut from the same pattern: the same panels in the same order, each with the
// same rest (pattern) coordinates up to how finely its outline is divided.
#pragma once

#include "core/garment.h"

#include <vector>

namespace tightfit {

// The welded positions of `fine` from those of `coarse` (`coarse_m`, one per welded vertex):
// each fine panel vertex goes where its rest coordinates fall in the coarse panel, by the
// barycentric coordinates of the coarse rest triangle of that panel nearest to it (inside
// one, or outside the coarse outline where the fine one bulges past a chord: extrapolated
// from the nearest). A position field linear in the rest coordinates over a panel is carried
// exactly. A welded vertex goes to the mean of its panel copies (one per panel it lies on).
// Throws std::invalid_argument when the meshes do not have the same number of panels or a
// panel has no coarse triangle, or `coarse_m` has the wrong size.
std::vector<Vec3> transfer_positions(const SimulationMesh& coarse,
                                     const std::vector<Vec3>& coarse_m, const SimulationMesh& fine);

}  // namespace tightfit
