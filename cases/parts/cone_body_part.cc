// Body/Kind = cone: a rigid solid circular cone (a limb that tapers; bodies/cone.h). Its morph
// parameter alpha scales every distance from the axis about the apex (the cone grows as the
// paper's cylinder does); alpha = 1 is the cone as given, and a case with Final alpha = 1 has
// only the settling step.
#include "bodies/cone.h"
#include "cases/parts/part_entries.h"

#include <cstdio>
#include <stdexcept>

namespace tightfit {

namespace {

class ConeBody final : public ScenarioBody {
 public:
  explicit ConeBody(const ConeOptions& options) : cone_(options), options_(options) {}
  const RigidBody& body() const override { return cone_; }
  double initial_alpha() const override { return 1.0; }
  void morph(int step, double alpha) override { cone_.set_radial_scale(step == 0 ? 1.0 : alpha); }
  std::optional<Vec3> axis() const override { return options_.axis.normalized(); }
  std::string describe() const override {
    char line[200];
    std::snprintf(line, sizeof line,
                  "cone of half-angle %.3g deg, radius %.2f cm at (%g, %g, %g) m, widening along "
                  "(%g, %g, %g)",
                  options_.half_angle_deg, 100 * options_.radius_at_point_m,
                  options_.point_on_axis_m.x(), options_.point_on_axis_m.y(),
                  options_.point_on_axis_m.z(), options_.axis.x(), options_.axis.y(),
                  options_.axis.z());
    return line;
  }

 private:
  Cone cone_;
  ConeOptions options_;
};

}  // namespace

PartEntry<BodyMaker> cone_body_entry() {
  PartEntry<BodyMaker> e;
  e.name = "cone";
  e.subsection = "Cone";
  e.description =
      "a rigid circular cone, semi-infinite from its apex; alpha scales its radii about the axis.";
  e.declare_parameters = [](ParameterTree& prm) {
    prm.declare_vector("Axis point", "0,0,0", "A point on the cone's axis (m).");
    prm.declare_vector("Axis", "1,0,0", "Direction of the axis, towards the wider end (-).");
    prm.declare_double("Radius at axis point", 0.05, 0, ParameterTree::unbounded,
                       "Radius of the cone where its axis passes the axis point (m).");
    prm.declare_double("Half angle", 5, 0, 89,
                       "Angle between the cone's surface and its axis (degrees).");
    prm.declare_double("Display height", 0.24, 0, ParameterTree::unbounded,
                       "Length of cone drawn in the body's VTU, centred on the axis point (m).");
  };
  e.parse = [](ParameterTree& prm) -> BodyMaker {
    ConeOptions o;
    o.point_on_axis_m = prm.get_vector("Axis point");
    o.axis = prm.get_vector("Axis");
    o.radius_at_point_m = prm.get_double("Radius at axis point");
    o.half_angle_deg = prm.get_double("Half angle");
    o.display_length_m = prm.get_double("Display height");
    Cone check(o);  // throws for a zero axis, a radius or half-angle out of range
    return [=](const Garment&) -> std::unique_ptr<ScenarioBody> {
      return std::make_unique<ConeBody>(o);
    };
  };
  return e;
}

}  // namespace tightfit
