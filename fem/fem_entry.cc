#include "fem/fem_entry.h"

#include "fem/fem_backend.h"
#include "fem/fem_parameters.h"

namespace tightfit {

BackendEntry fem_backend_entry() {
  BackendEntry entry;
  entry.name = "fem";
  entry.subsection = "Finite elements";
  entry.applies_friction = true;
  entry.description =
      "Finite-element membrane (deal.II + PETSc): Newton's method on the static equilibrium, "
      "augmented-Lagrangian contact with Coulomb friction, seams as constraints; runs under "
      "mpirun.";
  entry.declare_parameters = [](dealii::ParameterHandler& prm) {
    FemParameters::declare_parameters(prm);
  };
  entry.create = [](const Problem& problem, const StopRule& stop,
                    dealii::ParameterHandler& prm) -> std::unique_ptr<Backend> {
    stop.validate(true);
    FemParameters parameters;
    parameters.parse_parameters(prm, stop.rough_mesh_body);
    parameters.stop = stop;
    return std::make_unique<FemBackend>(problem, parameters);
  };
  return entry;
}

}  // namespace tightfit
