// Body/Kind = plane: a rigid half-space (a floor, a table); load steps leave it as it is.
#include "bodies/plane.h"
#include "cases/parts/part_entries.h"

#include <cstdio>
#include <stdexcept>

namespace tightfit {

namespace {

class PlaneBody final : public ScenarioBody {
 public:
  PlaneBody(const Vec3& point_m, const Vec3& normal, double display_size_m)
      : plane_(point_m, normal, display_size_m), point_(point_m), normal_(normal.normalized()) {}
  const RigidBody& body() const override { return plane_; }
  double initial_alpha() const override { return 1.0; }
  void morph(int, double) override {}
  std::optional<Vec3> axis() const override { return normal_; }
  std::string describe() const override {
    char line[160];
    std::snprintf(line, sizeof line, "plane through (%g, %g, %g) m, normal (%g, %g, %g)",
                  point_.x(), point_.y(), point_.z(), normal_.x(), normal_.y(), normal_.z());
    return line;
  }

 private:
  Plane plane_;
  Vec3 point_, normal_;
};

}  // namespace

PartEntry<BodyMaker> plane_body_entry() {
  PartEntry<BodyMaker> e;
  e.name = "plane";
  e.subsection = "Plane";
  e.description = "a rigid half-space below a plane; it does not change between load steps.";
  e.declare_parameters = [](ParameterTree& prm) {
    prm.declare_vector("Point", "0,0,0", "A point on the plane (m).");
    prm.declare_vector("Normal", "0,0,1",
                       "Outward normal of the plane: the body lies behind it (-).");
    prm.declare_double("Display size", 0.5, 0, ParameterTree::unbounded,
                       "Side of the square drawn in the body's VTU (m); contact is unbounded.");
  };
  e.parse = [](ParameterTree& prm) -> BodyMaker {
    const Vec3 point = prm.get_vector("Point");
    const Vec3 normal = prm.get_vector("Normal");
    const double size_m = prm.get_double("Display size");
    if (!(normal.norm() > 0)) throw std::invalid_argument("Normal must not be zero");
    return [=](const Garment&) -> std::unique_ptr<ScenarioBody> {
      return std::make_unique<PlaneBody>(point, normal, size_m);
    };
  };
  return e;
}

}  // namespace tightfit
