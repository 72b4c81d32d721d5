// The coarse-to-fine dressing of Placement/Kind = dressing and arrangement (docs/dressing.md):
// dressed, and optionally settled, on the garment meshed coarser, then carried to the case's
// mesh.
#pragma once

#include "cases/case_parameters.h"
#include "core/dressing_stage.h"

#include <string>
#include <vector>

namespace tightfit {

// Coarse to fine (Coarse edge length): the case's garment meshed at `coarse_m` is dressed by
// `dress_coarse` in a scenario of its own; with a settle rule (a relative tolerance > 0) the
// welded coarse garment then settles as the case's first load step would (gravity, friction),
// on the dressing stage's backend (DressingStage::settle, core/dressing_stage.h), so that the
// slow slide of a dressed top over the body is done on the cheap mesh;
// its state is carried to the case's mesh in pattern space (core/mesh_transfer.h). Fine vertices on
// a coarse triangle's chord of the body may lie inside it by the chord's sagitta (h^2 / 8 R: about
// 2 mm for 30 mm edges round a 5 cm arm); up to a quarter of a coarse edge they go back onto the
// surface, as a dressing's own welded vertices do.
std::vector<Vec3> dressed_from_coarse(const Scenario& scenario, double coarse_m,
                                      const CoarseSettle& settle_rule,
                                      const PlacementMaker& dress_coarse,
                                      const std::string& section = "Placement/Dressing");

// The dressing's line for the log: the start vertices pushed out, the seams closed, the frames,
// the welded vertices put back on the body.
void print_dressing(const DressingResult& dressed);

}  // namespace tightfit
