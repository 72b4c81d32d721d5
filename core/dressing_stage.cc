#include "core/dressing_stage.h"

namespace tightfit {

void draw_seams_from_afar(DressingSettings& settings) {
  settings.stiffness_over_mass_ratio = 4.0;
  settings.limit_seam_pull = true;
  settings.sewn_stiffness_factor = 2.0;
  settings.growth_gap_fraction = 1.0;
}

}  // namespace tightfit
