#include "cases/parts/cylinder_body.h"
#include "cases/parts/part_entries.h"
#include "core/tube_garment.h"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace tightfit {

CylinderBody::CylinderBody(const Cylinder& cylinder, double reference_radius_m,
                           bool garment_is_tube)
    : cylinder_(cylinder),
      initial_radius_m_(cylinder.radius_m()),
      reference_radius_m_(reference_radius_m),
      garment_is_tube_(garment_is_tube) {}

void CylinderBody::morph(int step, double alpha) {
  cylinder_.set_radius(step == 0 ? initial_radius_m_ : alpha * reference_radius_m_);
}

void CylinderBody::check_final_alpha(double final_alpha) const {
  if (!garment_is_tube_ || final_alpha > 1.0) return;
  std::ostringstream message;
  message << "Protocol/Final alpha = " << final_alpha
          << ": the garment (rest radius R0 = " << reference_radius_m_ * 100
          << " cm) never presses on the cylinder; pressure needs alpha = r/R0 > 1";
  throw std::invalid_argument(message.str());
}

std::string CylinderBody::describe() const {
  char line[160];
  std::snprintf(line, sizeof line, "cylinder r0 = %.2f cm, R0 = %.3f cm", 100 * initial_radius_m_,
                100 * reference_radius_m_);
  return line;
}

const CylinderBody& cylinder_body_of(const ScenarioBody& body, const std::string& part) {
  const auto* cylinder = dynamic_cast<const CylinderBody*>(&body);
  if (!cylinder)
    throw std::invalid_argument(part + " needs Body/Kind = cylinder, not a " + body.body().name());
  return *cylinder;
}

PartEntry<BodyMaker> cylinder_body_entry() {
  PartEntry<BodyMaker> e;
  e.name = "cylinder";
  e.subsection = "Cylinder";
  e.description =
      "a rigid circular cylinder whose radius grows to alpha R0 (R0 the tube's rest radius).";
  e.declare_parameters = [](ParameterTree& prm) {
    prm.declare_double("Initial radius", 0.05, 0, ParameterTree::unbounded,
                       "Radius of the cylinder the garment first settles on (m). Table 3: 5 cm.");
    prm.declare_vector("Axis point", "0,0,0", "A point on the cylinder's axis (m).");
    prm.declare_vector("Axis", "1,0,0",
                       "Direction of the cylinder's axis (-). Horizontal by default, as in the "
                       "paper's Figure 13, so that gravity acts across it.");
    prm.declare_double("Display height", 0.24, 0, ParameterTree::unbounded,
                       "Length of cylinder drawn in the body's VTU (m); contact is unbounded.");
  };
  e.parse = [](ParameterTree& prm) -> BodyMaker {
    const double radius_m = prm.get_double("Initial radius");
    const Vec3 point = prm.get_vector("Axis point");
    const Vec3 axis = prm.get_vector("Axis");
    const double height_m = prm.get_double("Display height");
    if (!(axis.norm() > 0)) throw std::invalid_argument("Axis must not be zero");
    if (!(radius_m > 0)) throw std::invalid_argument("Initial radius must be positive (m)");
    return [=](const Garment& garment) -> std::unique_ptr<ScenarioBody> {
      const double circumference_m = ring_circumference_m(garment);
      const bool tube = circumference_m > 0;
      return std::make_unique<CylinderBody>(Cylinder(point, axis, radius_m, height_m),
                                            tube ? circumference_m / (2.0 * M_PI) : radius_m, tube);
    };
  };
  return e;
}

}  // namespace tightfit
