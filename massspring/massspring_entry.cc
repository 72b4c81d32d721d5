#include "massspring/massspring_entry.h"

#include "massspring/massspring_backend.h"
#include "massspring/massspring_dressing_stage.h"
#include "massspring/massspring_parameters.h"

#include <deal.II/base/parameter_handler.h>

#include <memory>
#include <string>
#include <vector>

namespace tightfit {

namespace {
// Whether the case dresses its garment from afar, arranged from the body's landmarks round its
// limbs or its torso (a handler without a Placement subsection, as a test's, does not): there
// the stick damper is on by default on a rough mesh body (flat faces or friction;
// massspring_parameters.h).
bool arranged_from_landmarks(const dealii::ParameterHandler& prm) {
  try {
    const std::string kind = prm.get(std::vector<std::string>{"Placement"}, "Kind");
    return kind == "pattern arrangement" || kind == "arrangement";
  } catch (...) {
    return false;
  }
}
}  // namespace

BackendEntry massspring_backend_entry() {
  BackendEntry entry;
  entry.name = "massspring";
  entry.subsection = "Mass spring";
  entry.applies_friction = true;
  entry.description =
      "The paper's mass-spring model (Section 2.1): lumped particles, Volino triangle "
      "elements, angular bending springs, RK4 with a quasi-static start; settings in the "
      "subsection 'Mass spring'.";
  entry.declare_parameters = [](dealii::ParameterHandler& prm) {
    MassSpringParameters::declare_parameters(prm);
  };
  entry.create = [](const Problem& problem, const StopRule& stop,
                    dealii::ParameterHandler& prm) -> std::unique_ptr<Backend> {
    MassSpringParameters parameters;
    parameters.parse_parameters(prm, stop.rough_mesh_body, arranged_from_landmarks(prm));
    parameters.stop = stop;
    parameters.validate();
    return std::make_unique<MassSpringBackend>(problem, parameters);
  };
  entry.dressing_stage = std::make_shared<MassSpringDressingStage>();
  return entry;
}

}  // namespace tightfit
