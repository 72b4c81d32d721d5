#include "massspring/open_seam_garment.h"

#include "bodies/rigid_body.h"
#include "contact/body_query_pool.h"
#include "contact/penalty_contact.h"
#include "massspring/lumped_mass.h"
#include "massspring/stable_time_step.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tightfit {

namespace {

const Problem& complete(const Problem& problem) {
  if (!problem.mesh || !problem.law || !problem.fabric)
    throw std::invalid_argument("mass spring: the problem needs a mesh, a law and a fabric");
  return problem;
}

// What the penalty contact's force asks of the body: the gap and the normal alone.
constexpr QueryParts kForceOnly{false, false, false};

}  // namespace

OpenSeamGarment::OpenSeamGarment(const Problem& problem, const MassSpringParameters& parameters)
    : problem_(complete(problem)),
      body_(problem.body),
      parameters_(parameters),
      panels_(unweld(*problem.mesh)),
      elements_(panels_.mesh, *problem.law),
      hinges_(panels_.mesh, parameters.bending_rigidity_N_m),
      full_seam_stiffness_N_per_m_(parameters.seam_stiffness_factor *
                                   problem.law->stiffness_scale()),
      seams_(panels_.seam_pairs, full_seam_stiffness_N_per_m_) {
  parameters_.validate();
  const SimulationMesh& welded = *problem_.mesh;
  mass_kg_ = lumped_masses_kg(panels_.mesh, problem_.fabric->areal_density_kg_per_m2);
  rest_vertex_area_m2_ = rest_vertex_areas_m2(panels_.mesh);
  // A constrained welded vertex constrains every copy.
  constrained_ =
      ConstrainedDirections(problem_.constraints, welded.n_vertices).copies(welded.welded_index);
  mean_edge_m_ = mean_rest_edge_length_m(welded);
  size_m_ = std::sqrt(rest_area(welded));
  for (auto* buffer : {&x_, &v_, &asked_at_m_})
    buffer->assign(panels_.mesh.n_vertices, Vec3::Zero());
  clearance_m_.assign(panels_.mesh.n_vertices, 0.0);
  near_.assign(panels_.mesh.n_vertices, NearFaces{});
  contact_N_.assign(panels_.mesh.n_vertices, Vec3::Zero());
  asked_.assign(panels_.mesh.n_vertices, 0);
  set_body(body_);
}

void OpenSeamGarment::set_body(const RigidBody* body) {
  body_ = body;
  std::fill(clearance_m_.begin(), clearance_m_.end(), 0.0);
  if (!pool_) pool_ = body_query_pool(body_, problem_.threads);
}

void OpenSeamGarment::body_moved(double bound_m) {
  for (double& c : clearance_m_) c -= bound_m;
}

void OpenSeamGarment::set_seam_fraction(double fraction) {
  std::vector<char> sewn = seams_.sewn();
  seams_ = SeamSprings(panels_.seam_pairs, fraction * full_seam_stiffness_N_per_m_);
  seams_.set_pull_limit(seam_pull_limit_N_);
  seams_.set_sewn_stiffness_factor(sewn_factor_);
  seams_.set_sewn(std::move(sewn));
}

void OpenSeamGarment::set_seam_pull_limit(double pull_limit_N, double sewn_factor) {
  seam_pull_limit_N_ = pull_limit_N;
  sewn_factor_ = sewn_factor;
  seams_.set_pull_limit(pull_limit_N);
  seams_.set_sewn_stiffness_factor(sewn_factor);
}

int OpenSeamGarment::limit_stiffness_over_mass(double ratio) {
  const std::vector<double> scaled = mass_scaled_kg(stiffness_bounds_N_per_m(), mass_kg_, ratio);
  int raised = 0;
  for (std::size_t i = 0; i < scaled.size(); ++i) raised += scaled[i] != mass_kg_[i];
  mass_kg_ = scaled;
  return raised;
}

void OpenSeamGarment::forces(const std::vector<Vec3>& x, bool gravity_on,
                             std::vector<Vec3>& force) const {
  std::fill(force.begin(), force.end(), Vec3::Zero());
  elements_.add_forces(x, force);
  hinges_.add_forces(x, force);
  seams_.add_forces(x, force);
  const double k = problem_.contact_stiffness_Pa_per_m;
  if (body_ && k > 0)
    for_each_part(body_->costly_queries() ? pool_.get() : nullptr, x.size(),
                  [&](std::size_t begin, std::size_t end) {
                    for (std::size_t i = begin; i < end; ++i) {
                      asked_[i] = !((x[i] - asked_at_m_[i]).norm() < clearance_m_[i]);
                      if (!asked_[i]) continue;
                      // The penalty force needs the gap and the normal alone: without the
                      // closest point and location a smooth surface skips their Newton steps
                      // and answers a vertex that stays within micrometres by its last
                      // answer's expansion (RigidBody::query_parts).
                      const SurfacePoint s = body_->query_parts(x[i], near_[i], kForceOnly);
                      asked_at_m_[i] = x[i];
                      clearance_m_[i] = clearance_factor_ * s.signed_distance_m;
                      contact_N_[i] = penalty_force_N(s, k, rest_vertex_area_m2_[i]);
                    }
                  });
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (body_ && k > 0 && asked_[i]) force[i] += contact_N_[i];
    if (gravity_on) force[i] += mass_kg_[i] * problem_.gravity_m_per_s2;
    if (constrained_.constrained(i)) constrained_.remove_constrained(i, force[i]);
  }
}

void OpenSeamGarment::rk4_frame(double dt, double c, bool gravity_on) {
  integrator_.frame(
      x_, v_, mass_kg_, dt, c,
      [&](const std::vector<Vec3>& x, const std::vector<Vec3>&, std::vector<Vec3>& force) {
        forces(x, gravity_on, force);
        return 0.0;
      });
  for (std::size_t i = 0; i < x_.size(); ++i)
    if (constrained_.constrained(i)) constrained_.remove_constrained(i, v_[i]);
}

double OpenSeamGarment::time_step_s() const {
  if (parameters_.time_step_s > 0) return parameters_.time_step_s;
  return stable_time_step_s(stiffness_bounds_N_per_m(), mass_kg_, parameters_.time_step_safety);
}

std::vector<double> OpenSeamGarment::stiffness_bounds_N_per_m() const {
  std::vector<double> stiffness(x_.size(), 0.0);
  elements_.add_stiffness_bounds(x_, stiffness);
  hinges_.add_stiffness_bounds(x_, stiffness);
  // The full seam stiffness, whatever the ramp: the step stays stable as the ramp rises.
  SeamSprings full(panels_.seam_pairs, full_seam_stiffness_N_per_m_);
  full.set_sewn_stiffness_factor(sewn_factor_);
  full.add_stiffness_bounds(stiffness);
  for (std::size_t i = 0; i < x_.size(); ++i)
    stiffness[i] += problem_.contact_stiffness_Pa_per_m * rest_vertex_area_m2_[i];
  return stiffness;
}

double OpenSeamGarment::damping_per_s() const {
  return parameters_.damping_per_s > 0
             ? parameters_.damping_per_s
             : critical_damping_per_s(problem_.law->stiffness_scale(),
                                      problem_.fabric->areal_density_kg_per_m2, size_m_);
}

std::pair<int, int> OpenSeamGarment::widest_seam_pair() const {
  std::pair<int, int> widest{-1, -1};
  double largest = -1.0;
  for (const auto& [a, b] : panels_.seam_pairs) {
    const double gap = (x_[a] - x_[b]).squaredNorm();
    if (gap > largest) largest = gap, widest = {a, b};
  }
  return widest;
}

}  // namespace tightfit
