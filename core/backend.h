// The one interface the two cloth backends implement. Everything before it (what is
// simulated) and after it (what is measured) is shared, so a comparison compares solvers.
#pragma once

#include "core/garment.h"
#include "core/material.h"
#include "core/step_report.h"
#include "core/surface_state.h"

#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace tightfit {

class RigidBody;

// A constraint on a named set of welded vertices (a SimulationMesh::vertex_groups entry such
// as "bottom" or "top"): the case file's Constraints subsection.
struct VertexConstraint {
  enum class Kind {
    held_along_direction,  // the vertices keep their coordinate along `direction`
    fixed,                 // the vertices do not move at all
  };
  Kind kind = Kind::held_along_direction;
  std::string group;               // the vertex group's name, for messages
  std::vector<int> vertices;       // welded vertex indices
  Vec3 direction = Vec3::UnitZ();  // held_along_direction only
};

// What is simulated: shared by both backends, owned by the caller, alive while they run.
struct Problem {
  // The mass-spring backend reads it on every rank. The FE backend reads it (and `constraints`)
  // on the first rank of MPI_COMM_WORLD only, and sends each rank its part: with linear
  // triangles the other ranks may leave it null (quadratic ones need it on every rank).
  const SimulationMesh* mesh = nullptr;
  const MaterialLaw* law = nullptr;
  const FabricParameters* fabric = nullptr;
  // The body; the caller changes its shape between load steps.
  const RigidBody* body = nullptr;
  // Penalty contact: pressure per unit penetration depth, Pa/m.
  double contact_stiffness_Pa_per_m = 0.0;
  // Coulomb friction (contact/friction_anchors.h): the coefficient mu (0: frictionless) and the
  // tangential penalty per unit rest area, Pa/m (a vertex's k_t is this times its rest area).
  double friction_coefficient = 0.0;
  double tangential_stiffness_Pa_per_m = 0.0;
  // Vertices held along a direction or fixed; none for a garment free on the body.
  std::vector<VertexConstraint> constraints;
  // Gravity when a load step turns it on, m/s^2.
  Vec3 gravity_m_per_s2 = Vec3(0.0, 0.0, -9.81);
  // The threads a backend may share its per-vertex body queries out to (>= 1; Solver/Threads,
  // resolved by core/thread_count.h): the answers are the same with any number.
  int threads = 1;
};

struct LoadStep {
  int index = 0;
  double alpha = 1.0;  // the body's morph parameter (a cylinder's r / R0), for messages
  bool gravity_on = false;
};

// Which load step failed and how far from the stop rule, as fields (load_step_failure,
// core/load_step_report.h, fills them); step_index -1: the error did not come from a load
// step's solve (a dressing, a placement), or the fields were not kept.
struct StepFailure {
  std::string backend;  // "mass spring", "fem backend"
  int step_index = -1;
  double alpha = 0.0;
  double residual_N = 0.0;   // the stop rule's residual when the step gave up
  double tolerance_N = 0.0;  // the stop rule's threshold
};

// Thrown when a backend cannot reach equilibrium; the message names the step and residual for
// the user, reason() and failure() say why and where as fields (core/step_report.h), for the
// code and the tests.
class SolverError : public std::runtime_error {
 public:
  SolverError(StopReason reason, const std::string& message)
      : std::runtime_error(message), reason_(reason) {}
  SolverError(StopReason reason, const std::string& message, const StepFailure& failure)
      : std::runtime_error(message),
        reason_(reason),
        failure_(std::make_shared<const StepFailure>(failure)) {}
  StopReason reason() const { return reason_; }
  const StepFailure& failure() const {
    static const StepFailure none;
    return failure_ ? *failure_ : none;
  }

 private:
  StopReason reason_;
  // Shared, so that copying the exception cannot throw (as std::runtime_error's message).
  std::shared_ptr<const StepFailure> failure_;
};

class Backend {
 public:
  virtual ~Backend() = default;
  virtual std::string name() const = 0;
  // Positions of the welded vertices to start from, m.
  virtual void set_positions(const std::vector<Vec3>& positions_m) = 0;
  // Brings the garment to static equilibrium against the body as it is now.
  // Returns only at equilibrium (stop_reason converged: the residual below the stop rule's
  // threshold, the contact gap closed) and throws SolverError otherwise.
  virtual StepReport solve(const LoadStep& step) = 0;
  // The equilibrium just reached (or the current state after a failure).
  virtual SurfaceState state() const = 0;
  // Optional per-vertex arrays a backend adds to the garment output beside the shared
  // extractor's (name, one value per welded vertex), e.g. its own contact traction in Pa.
  virtual std::vector<std::pair<std::string, std::vector<double>>> extra_point_data() const {
    return {};
  }
};

}  // namespace tightfit
