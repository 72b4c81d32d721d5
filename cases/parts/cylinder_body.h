// Body/Kind = cylinder: the paper's rigid cylinder, grown between load steps (Section 4.3).
// Its morph parameter is alpha = r / R0, R0 the rest radius of a tube garment (its
// circumference over 2 pi), or the initial radius when the garment is not a tube.
#pragma once

#include "bodies/cylinder.h"
#include "cases/scenario_body.h"

#include <string>

namespace tightfit {

class CylinderBody final : public ScenarioBody {
 public:
  CylinderBody(const Cylinder& cylinder, double reference_radius_m, bool garment_is_tube);

  const RigidBody& body() const override { return cylinder_; }
  double initial_alpha() const override { return initial_radius_m_ / reference_radius_m_; }
  void morph(int step, double alpha) override;
  void check_final_alpha(double final_alpha) const override;
  bool must_touch(double alpha) const override { return garment_is_tube_ && alpha > 1.001; }
  std::optional<Vec3> axis() const override { return cylinder_.axis(); }
  std::string describe() const override;

  const Cylinder& cylinder() const { return cylinder_; }
  // R0: the radius at alpha = 1, m.
  double reference_radius_m() const { return reference_radius_m_; }

 private:
  Cylinder cylinder_;
  double initial_radius_m_;
  double reference_radius_m_;
  bool garment_is_tube_;
};

// The scenario's body as a cylinder; throws std::invalid_argument saying that `part` (e.g.
// "Placement/Kind = tube round cylinder") needs Body/Kind = cylinder.
const CylinderBody& cylinder_body_of(const ScenarioBody& body, const std::string& part);

}  // namespace tightfit
