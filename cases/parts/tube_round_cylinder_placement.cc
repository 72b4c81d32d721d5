// Placement/Kind = tube round cylinder: the tube already sewn, as a circle coaxial with the
// cylinder (bodies/tube_placement.h), stress-free at its rest radius R0 when that is outside
// the cylinder, else just outside the body.
#include "bodies/tube_placement.h"
#include "cases/parts/cylinder_body.h"
#include "cases/parts/part_entries.h"
#include "cases/scenario.h"

#include <algorithm>

namespace tightfit {

PartEntry<PlacementMaker> tube_round_cylinder_placement_entry() {
  PartEntry<PlacementMaker> e;
  e.name = "tube round cylinder";
  e.subsection = "Tube round cylinder";
  e.description = "the sewn tube as a circle round the cylinder, at R0 or just outside the body.";
  e.declare_parameters = [](ParameterTree& prm) {
    prm.declare_double("Clearance", 0.005, 0, 1,
                       "When the tube is tighter than the body, it starts this fraction of the "
                       "body's radius outside it (-).");
  };
  e.parse = [](ParameterTree& prm) -> PlacementMaker {
    const double clearance = prm.get_double("Clearance");
    return [=](const Scenario& scenario) {
      const CylinderBody& body =
          cylinder_body_of(*scenario.body, "Placement/Kind = tube round cylinder");
      const double radius_m =
          std::max(body.reference_radius_m(), (1.0 + clearance) * body.cylinder().radius_m());
      return place_tube_round_cylinder(scenario.garment, scenario.mesh, body.cylinder(), radius_m);
    };
  };
  return e;
}

}  // namespace tightfit
