// Dressing a body (docs/dressing.md): the garment's panels, unsewn, start round the body
// (wherever the caller put them, outside it), the body shrunk about a centre. Zero-rest-length
// seam springs, their stiffness ramped up from zero, pull every seam vertex pair together while
// the membrane, the bending springs and the penalty contact act, and the body grows back to its
// own shape; when every seam pair is closer than the closing gap and the body is whole, the
// seams are welded (each welded vertex at the mean of its copies) and the garment is handed to
// the load steps, which settle it as usual. It is the paper's flat-panel start (Section 4.3,
// FlatPanelStart) for any body and any pattern.
#pragma once

#include "core/dressing_stage.h"

#include <string>
#include <vector>

namespace tightfit {

// DressingStage::dress (core/dressing_stage.h) on this backend: RK4 frames of the membrane, the
// bending springs, the seam springs and the penalty contact, at the backend's default time
// step, quasi-static start and bending rigidity, the settings' seam stiffness and damping.
DressingResult dress(const Problem& problem, const Garment& garment,
                     const std::vector<Vec3>& start_m, const DressingSettings& settings);

// "front:3 -- back:3 mirrored": the seam of `garment` that joins unwelded vertices a and b of
// its welded mesh, or the two panels and vertices when no seam lists them both.
std::string seam_joining(const Garment& garment, const SimulationMesh& mesh, int a, int b);

}  // namespace tightfit
