// Placement/Kind = tube round axis: the tube already sewn, as a circle of a given radius round
// an axis (a cone's, or one through a mesh body's limb or waist), its middle at a given point.
// The radius must clear the body all round: a tube that starts inside the body stops the case
// (the scenario's start check, cases/scenario.h).
#include "bodies/tube_placement.h"
#include "cases/parts/part_entries.h"
#include "cases/scenario.h"

#include <stdexcept>

namespace tightfit {

PartEntry<PlacementMaker> tube_round_axis_placement_entry() {
  PartEntry<PlacementMaker> e;
  e.name = "tube round axis";
  e.subsection = "Tube round axis";
  e.description =
      "the sewn tube as a circle of a given radius round an axis, its middle at a given point.";
  e.declare_parameters = [](ParameterTree& prm) {
    prm.declare_vector("Centre", "0,0,0", "Where the axis passes the middle of the tube (m).");
    prm.declare_text("Axis", "body",
                     "Direction of the tube's axis, three numbers x,y,z (-), 'body' for the "
                     "body's own axis (a cone's or a cylinder's), or 'garment' for the limb's "
                     "axis a garment cut to the body was cut along (Garment/Kind = limb tube), "
                     "the tube's middle then on it (Centre is not read).");
    prm.declare_double("Radius", 0.1, 0, ParameterTree::unbounded,
                       "Radius of the tube's circle at the start (m): larger than the body "
                       "wherever the tube lies, so that it shrinks onto it.");
    prm.declare_double("Stretch", 0, 0, ParameterTree::unbounded,
                       "If positive, each ring of the tube is placed at this many times its own "
                       "rest radius (its relaxed girth over 2 pi) instead of at Radius: a tapered "
                       "tube stretched evenly along its length (-). 0: every ring at Radius.");
    prm.declare_double("Clearance", 0, 0, ParameterTree::unbounded,
                       "If positive, each ring is centred on the centroid of the body's section "
                       "in its plane (normal to Axis, the section round the axis) and placed this "
                       "far outside that section's farthest point, instead of Radius and Stretch: "
                       "a tube that follows a bent limb (m; docs/stocking.md).");
  };
  e.parse = [](ParameterTree& prm) -> PlacementMaker {
    const Vec3 centre = prm.get_vector("Centre");
    const std::string axis_text = prm.get("Axis");
    const double radius_m = prm.get_double("Radius");
    const double stretch = prm.get_double("Stretch");
    const double clearance_m = prm.get_double("Clearance");
    if (!(radius_m > 0) && !(stretch > 0) && !(clearance_m > 0))
      throw std::invalid_argument("Radius must be positive (m)");
    std::optional<Vec3> axis;
    const bool along_garment = axis_text == "garment";
    if (axis_text != "body" && !along_garment) {
      axis = prm.get_vector("Axis");
      if (!(axis->norm() > 0)) throw std::invalid_argument("Axis must not be zero");
    }
    return [=](const Scenario& scenario) {
      if (along_garment && !scenario.garment_line)
        throw std::invalid_argument(
            "Placement/Tube round axis/Axis = garment, but the garment (Garment/Kind) is not cut "
            "along a limb's axis: give a direction x,y,z and a Centre");
      const std::optional<Vec3> direction = along_garment ? scenario.garment_line->axis
                                            : axis        ? axis
                                                          : scenario.body->axis();
      const Vec3 middle = along_garment ? scenario.garment_line->centre_m : centre;
      if (!direction)
        throw std::invalid_argument("Placement/Tube round axis/Axis = body, but the body (" +
                                    scenario.body->describe() +
                                    ") has no axis: give a direction x,y,z");
      if (clearance_m > 0) {
        const DisplayMesh body = scenario.body->body().display_mesh();
        TriangleSurface surface;
        surface.vertices_m = body.vertices_m;
        surface.triangles = body.triangles;
        return place_tube_round_limb(scenario.garment, scenario.mesh, middle, *direction, surface,
                                     clearance_m);
      }
      return place_tube_round_axis(scenario.garment, scenario.mesh, middle, *direction, radius_m,
                                   stretch);
    };
  };
  return e;
}

}  // namespace tightfit
