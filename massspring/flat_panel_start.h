// The paper's start of the cylinder study (Section 4.3, Figure 5): the two panels, unsewn,
// lie flat on opposite sides of the cylinder; zero-rest-length seam springs pull each seam
// vertex pair together while the membrane, the bending springs and the penalty contact act,
// so the panels wrap round the cylinder. Integrated like every load step (quasi-static frames,
// then damped RK4) until the seams have closed; then the seams are welded and the sewn
// garment carries on from there (MassSpringBackend).
#pragma once

#include "bodies/cylinder.h"
#include "core/backend.h"
#include "massspring/massspring_parameters.h"
#include "massspring/open_seam_garment.h"

#include <vector>

namespace tightfit {

struct FlatPanelResult {
  std::vector<Vec3> welded_positions_m;  // each welded vertex at the mean of its copies
  int frames = 0;
  double largest_seam_gap_m = 0.0;  // at the last frame, before welding
  double closed_below_m = 0.0;      // the threshold it met
  double wall_seconds = 0.0;
};

class FlatPanelStart {
 public:
  // Seams count as closed when every seam vertex pair is closer than this fraction of the
  // mean rest edge length: welding then moves no vertex by more than half of it, which the
  // sewn garment's own settling absorbs in a few frames.
  static constexpr double closed_fraction = 0.05;

  // `problem` (and what it points to) must outlive this object. Throws std::invalid_argument
  // when the body is not a Cylinder or the garment has fewer than two panels.
  FlatPanelStart(const Problem& problem, const MassSpringParameters& parameters);

  // The unwelded positions of the flat panels round the cylinder as it is now, m: each panel
  // at the cylinder's radius + Placement gap from the axis.
  std::vector<Vec3> flat_positions_m() const;
  // Places the panels flat and integrates until the seams close. Throws SolverError naming
  // `step` when they have not closed within Mass spring/Maximum frames or the motion diverges.
  FlatPanelResult run(const LoadStep& step);

  const UnweldedPanels& panels() const { return garment_.panels(); }

 private:
  Problem problem_;
  const Cylinder* cylinder_;
  MassSpringParameters parameters_;
  OpenSeamGarment garment_;
};

}  // namespace tightfit
