#include "massspring/massspring_dressing_stage.h"

#include "massspring/dressing.h"
#include "massspring/massspring_backend.h"

namespace tightfit {

DressingResult MassSpringDressingStage::dress(const Problem& problem, const Garment& garment,
                                              const std::vector<Vec3>& start_m,
                                              const DressingSettings& settings) const {
  return tightfit::dress(problem, garment, start_m, settings);
}

SettledGarment MassSpringDressingStage::settle(const Problem& problem,
                                               const std::vector<Vec3>& dressed_m,
                                               const LoadStep& step,
                                               const CoarseSettle& rule) const {
  MassSpringParameters parameters =
      rule.rough_mesh_body ? MassSpringParameters::on_rough_mesh_body() : MassSpringParameters{};
  parameters.stop.norm = StopNorm::rms;
  parameters.stop.relative_tolerance = rule.relative_tolerance;
  // A quick settle that carries positions, not pressures: the tension-scale rule alone.
  parameters.stop.contact_load_tolerance = 0.0;
  // The rough mesh body's contact damper, time step updates, net force rule and creep slide
  // (massspring_parameters.h): the coarse garment settles as the case's own would.
  if (rule.net_force_tolerance > 0) parameters.net_force_tolerance = rule.net_force_tolerance;
  if (!(parameters.net_force_tolerance > 0)) parameters.creep_slide_damping_per_s = 0.0;
  parameters.slide_damping_per_s = rule.slide_damping_per_s;
  parameters.contact_updates = 0;
  MassSpringBackend backend(problem, parameters);
  backend.set_positions(dressed_m);
  SettledGarment settled;
  settled.report = backend.solve(step);
  settled.positions_m = backend.state().positions_m;
  return settled;
}

}  // namespace tightfit
