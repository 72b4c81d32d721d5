// The body of a scenario: a rigid body (bodies/rigid_body.h) whose shape the load steps
// change through one number, the body's morph parameter alpha (a cylinder: its radius over the
// garment's rest radius, r / R0; a body that does not change ignores it).
#pragma once

#include "bodies/rigid_body.h"

#include <optional>
#include <string>

namespace tightfit {

class ScenarioBody {
 public:
  virtual ~ScenarioBody() = default;
  virtual const RigidBody& body() const = 0;
  // The morph parameter of the body as the garment first settles on it.
  virtual double initial_alpha() const = 0;
  // Shapes the body for a load step: the settling step (step 0) restores the initial shape,
  // every later one takes the shape of morph parameter `alpha`.
  virtual void morph(int step, double alpha) = 0;
  // Checks the schedule's last morph parameter; throws std::invalid_argument naming the entry
  // when the garment could never press on the body (a tube never smaller than the cylinder).
  virtual void check_final_alpha(double /*final_alpha*/) const {}
  // Whether the garment must touch the body at morph parameter `alpha` (a tube stretched over
  // a cylinder must): a run that loses contact there stops with a SolverError.
  virtual bool must_touch(double /*alpha*/) const { return false; }
  // The body's own direction, if it has one (a cylinder's axis, a plane's normal): what
  // Constraints/Held direction = axis holds along.
  virtual std::optional<Vec3> axis() const { return std::nullopt; }
  // One line for the case header.
  virtual std::string describe() const = 0;
};

}  // namespace tightfit
