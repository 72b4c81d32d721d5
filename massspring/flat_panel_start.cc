#include "massspring/flat_panel_start.h"

#include "core/interruption.h"
#include "massspring/flat_panel_placement.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace tightfit {

namespace {

// The body the panels are laid round: only a cylinder has the two "opposite sides" of the
// paper's placement.
const Cylinder* cylinder_body(const Problem& problem) {
  if (!problem.mesh || !problem.law || !problem.fabric)
    throw std::invalid_argument("mass spring: the problem needs a mesh, a law and a fabric");
  const auto* cylinder = dynamic_cast<const Cylinder*>(problem.body);
  if (!cylinder)
    throw std::invalid_argument(
        std::string("mass spring: Placement = flat panels needs a cylinder body (the panels "
                    "are laid flat on opposite sides of its axis, paper Section 4.3); this "
                    "problem's body is ") +
        (problem.body ? "a " + problem.body->name() : std::string("missing")) +
        ". Use Placement = sewn tube.");
  return cylinder;
}

}  // namespace

FlatPanelStart::FlatPanelStart(const Problem& problem, const MassSpringParameters& parameters)
    : problem_(problem),
      cylinder_(cylinder_body(problem)),
      parameters_(parameters),
      garment_(problem, parameters) {
  // Fails early (fewer than two panels) rather than at the first load step.
  flat_positions_m();
}

std::vector<Vec3> FlatPanelStart::flat_positions_m() const {
  return place_panels_flat(*problem_.mesh, *cylinder_,
                           cylinder_->radius_m() + parameters_.placement_gap_m);
}

FlatPanelResult FlatPanelStart::run(const LoadStep& step) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<Vec3>& x = garment_.positions();
  std::vector<Vec3>& v = garment_.velocities();
  x = flat_positions_m();
  std::fill(v.begin(), v.end(), Vec3::Zero());
  const std::vector<Vec3> start_x = x;
  const double runaway_m = 10.0 * garment_.size_m();
  const double damping = garment_.damping_per_s();
  FlatPanelResult result;
  result.closed_below_m = closed_fraction * garment_.mean_edge_m();
  double dt = 0.0;

  auto fail = [&](StopReason reason, const std::string& what) {
    std::ostringstream message;
    message << "mass spring: load step " << step.index << " (alpha " << step.alpha
            << ") flat-panel start (Placement = flat panels): " << what << " at frame "
            << result.frames << " (largest seam gap " << result.largest_seam_gap_m
            << " m, closed below " << result.closed_below_m << " m, time step " << dt << " s)";
    return SolverError(reason, message.str());
  };

  result.largest_seam_gap_m = garment_.largest_seam_gap_m();
  while (!(result.largest_seam_gap_m < result.closed_below_m)) {
    if (result.frames >= parameters_.maximum_frames)
      throw fail(StopReason::seams_not_closed,
                 "the seams did not close within Mass spring/Maximum frames");
    throw_if_interrupted(interruption_signal(), "during the flat-panel start of load step " +
                                                    std::to_string(step.index) + " at frame " +
                                                    std::to_string(result.frames));
    // Chosen every frame: the seam springs stretch the panels' edges fast, and a stiffening
    // law's tangent grows with them. The start lasts tens of frames, so this costs little.
    dt = garment_.time_step_s();
    // The paper's quasi-static start (Section 4.3): velocity ignored, reset every frame.
    const bool quasi_static = result.frames < parameters_.quasi_static_frames;
    if (quasi_static) std::fill(v.begin(), v.end(), Vec3::Zero());
    garment_.rk4_frame(dt, quasi_static ? 0.0 : damping, step.gravity_on);
    ++result.frames;
    result.largest_seam_gap_m = garment_.largest_seam_gap_m();
    if (!std::isfinite(result.largest_seam_gap_m))
      throw fail(StopReason::not_finite,
                 "diverged (non-finite position; try a smaller Mass spring/Time step)");
    for (std::size_t i = 0; i < x.size(); ++i)
      if (!((x[i] - start_x[i]).norm() < runaway_m))
        throw fail(StopReason::ran_away,
                   "diverged (panel vertex " + std::to_string(i) + " ran away)");
  }
  result.welded_positions_m = weld_positions(*problem_.mesh, x);
  result.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace tightfit
