// The mass-spring backend's dressing stage, as the backend registry hands it out
// (core/dressing_stage.h): the dressing of massspring/dressing.h, and the settle of a dressed
// garment on this backend.
#pragma once

#include "core/dressing_stage.h"

namespace tightfit {

class MassSpringDressingStage : public DressingStage {
 public:
  DressingResult dress(const Problem& problem, const Garment& garment,
                       const std::vector<Vec3>& start_m,
                       const DressingSettings& settings) const override;
  // On MassSpringBackend with its default settings for the body (a rough mesh body's:
  // MassSpringParameters::on_rough_mesh_body) and the rule's rms stop rule, net force tolerance
  // (0: the default's) and slide damping, without contact multiplier updates.
  SettledGarment settle(const Problem& problem, const std::vector<Vec3>& dressed_m,
                        const LoadStep& step, const CoarseSettle& rule) const override;
};

}  // namespace tightfit
