#include "massspring/flat_panel_start.h"

#include "contact/penalty_contact.h"
#include "core/interruption.h"
#include "massspring/flat_panel_placement.h"
#include "massspring/lumped_mass.h"
#include "massspring/stable_time_step.h"

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
      panels_(unweld(*problem.mesh)),
      elements_(panels_.mesh, *problem.law),
      hinges_(panels_.mesh, parameters.bending_rigidity_N_m),
      seams_(panels_.seam_pairs,
             parameters.seam_stiffness_factor * problem.law->stiffness_scale()) {
  parameters_.validate();
  const SimulationMesh& welded = *problem_.mesh;
  const int n = panels_.mesh.n_vertices;
  mass_kg_ = lumped_masses_kg(panels_.mesh, problem_.fabric->areal_density_kg_per_m2);
  rest_vertex_area_m2_ = rest_vertex_areas_m2(panels_.mesh);
  // A constrained welded vertex constrains every copy: the flat panels keep the sewn tube's
  // axial coordinates, so the held ends start where the sewn start would put them.
  constrained_ =
      ConstrainedDirections(problem_.constraints, welded.n_vertices).copies(welded.welded_index);
  mean_edge_m_ = mean_rest_edge_length_m(welded);
  size_m_ = std::sqrt(rest_area(welded));
  // Fails early (fewer than two panels) rather than at the first load step.
  flat_positions_m();
  for (auto* buffer : {&x_, &v_}) buffer->assign(n, Vec3::Zero());
}

std::vector<Vec3> FlatPanelStart::flat_positions_m() const {
  return place_panels_flat(*problem_.mesh, *cylinder_,
                           cylinder_->radius_m() + parameters_.placement_gap_m);
}

void FlatPanelStart::forces(const std::vector<Vec3>& x, bool gravity_on,
                            std::vector<Vec3>& force) const {
  std::fill(force.begin(), force.end(), Vec3::Zero());
  elements_.add_forces(x, force);
  hinges_.add_forces(x, force);
  seams_.add_forces(x, force);
  const double k = problem_.contact_stiffness_Pa_per_m;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (k > 0) force[i] += penalty_force_N(cylinder_->query(x[i]), k, rest_vertex_area_m2_[i]);
    if (gravity_on) force[i] += mass_kg_[i] * problem_.gravity_m_per_s2;
    if (constrained_.constrained(i)) constrained_.remove_constrained(i, force[i]);
  }
}

void FlatPanelStart::rk4_frame(double dt, double c, bool gravity_on) {
  integrator_.frame(x_, v_, mass_kg_, dt, c,
                    [&](const std::vector<Vec3>& x, std::vector<Vec3>& force) {
                      forces(x, gravity_on, force);
                      return 0.0;
                    });
  for (std::size_t i = 0; i < x_.size(); ++i)
    if (constrained_.constrained(i)) constrained_.remove_constrained(i, v_[i]);
}

double FlatPanelStart::choose_time_step_s() const {
  if (parameters_.time_step_s > 0) return parameters_.time_step_s;
  std::vector<double> stiffness(x_.size(), 0.0);
  elements_.add_stiffness_bounds(x_, stiffness);
  hinges_.add_stiffness_bounds(x_, stiffness);
  seams_.add_stiffness_bounds(stiffness);
  for (std::size_t i = 0; i < x_.size(); ++i)
    stiffness[i] += problem_.contact_stiffness_Pa_per_m * rest_vertex_area_m2_[i];
  return stable_time_step_s(stiffness, mass_kg_, parameters_.time_step_safety);
}

FlatPanelResult FlatPanelStart::run(const LoadStep& step) {
  const auto start = std::chrono::steady_clock::now();
  x_ = flat_positions_m();
  std::fill(v_.begin(), v_.end(), Vec3::Zero());
  const std::vector<Vec3> start_x = x_;
  const double runaway_m = 10.0 * size_m_;
  const double damping =
      parameters_.damping_per_s > 0
          ? parameters_.damping_per_s
          : critical_damping_per_s(problem_.law->stiffness_scale(),
                                   problem_.fabric->areal_density_kg_per_m2, size_m_);
  FlatPanelResult result;
  result.closed_below_m = closed_fraction * mean_edge_m_;
  double dt = 0.0;

  auto fail = [&](const std::string& what) {
    std::ostringstream message;
    message << "mass spring: load step " << step.index << " (alpha " << step.alpha
            << ") flat-panel start (Placement = flat panels): " << what << " at frame "
            << result.frames << " (largest seam gap " << result.largest_seam_gap_m
            << " m, closed below " << result.closed_below_m << " m, time step " << dt << " s)";
    return SolverError(message.str());
  };

  result.largest_seam_gap_m = seams_.largest_gap_m(x_);
  while (!(result.largest_seam_gap_m < result.closed_below_m)) {
    if (result.frames >= parameters_.maximum_frames)
      throw fail("the seams did not close within Mass spring/Maximum frames");
    throw_if_interrupted(interruption_signal(), "during the flat-panel start of load step " +
                                                    std::to_string(step.index) + " at frame " +
                                                    std::to_string(result.frames));
    // Chosen every frame: the seam springs stretch the panels' edges fast, and a stiffening
    // law's tangent grows with them. The start lasts tens of frames, so this costs little.
    dt = choose_time_step_s();
    // The paper's quasi-static start (Section 4.3): velocity ignored, reset every frame.
    const bool quasi_static = result.frames < parameters_.quasi_static_frames;
    if (quasi_static) std::fill(v_.begin(), v_.end(), Vec3::Zero());
    rk4_frame(dt, quasi_static ? 0.0 : damping, step.gravity_on);
    ++result.frames;
    result.largest_seam_gap_m = seams_.largest_gap_m(x_);
    if (!std::isfinite(result.largest_seam_gap_m))
      throw fail("diverged (non-finite position; try a smaller Mass spring/Time step)");
    for (std::size_t i = 0; i < x_.size(); ++i)
      if (!((x_[i] - start_x[i]).norm() < runaway_m))
        throw fail("diverged (panel vertex " + std::to_string(i) + " ran away)");
  }
  result.welded_positions_m = weld_positions(*problem_.mesh, x_);
  result.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace tightfit
