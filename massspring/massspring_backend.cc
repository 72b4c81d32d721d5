#include "massspring/massspring_backend.h"
#include "core/interruption.h"

#include "contact/nodal_contact.h"
#include "contact/penalty_contact.h"
#include "contact/residual_location.h"
#include "contact/rigid_body.h"
#include "core/residual_history.h"
#include "core/tension_scale.h"
#include "massspring/flat_panel_start.h"
#include "massspring/lumped_mass.h"
#include "massspring/stable_time_step.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace tightfit {

namespace {

const Problem& checked(const Problem& problem) {
  if (!problem.mesh || !problem.law || !problem.fabric)
    throw std::invalid_argument("mass spring: the problem needs a mesh, a law and a fabric");
  if (problem.contact_stiffness_Pa_per_m < 0)
    throw std::invalid_argument("mass spring: the contact stiffness must be >= 0 (Pa/m)");
  return problem;
}

std::string step_name(const LoadStep& step) {
  std::ostringstream out;
  out << "load step " << step.index << " (alpha " << step.alpha << ")";
  return out.str();
}

}  // namespace

MassSpringBackend::MassSpringBackend(const Problem& problem, const MassSpringParameters& parameters)
    : problem_(checked(problem)),
      parameters_(parameters),
      elements_(*problem.mesh, *problem.law),
      hinges_(*problem.mesh, parameters.bending_rigidity_N_m) {
  parameters_.validate();
  const SimulationMesh& mesh = *problem_.mesh;
  const int n = mesh.n_vertices;
  mass_kg_ = lumped_masses_kg(mesh, problem_.fabric->areal_density_kg_per_m2);
  rest_vertex_area_m2_ = rest_vertex_areas_m2(mesh);
  constrained_ = ConstrainedDirections(problem_.constraints, n);
  size_m_ = std::sqrt(rest_area(mesh));
  // Stop rule: a force relative to the tension scale Y h^2 / L (core/garment.h says why).
  tolerance_N_ =
      parameters_.relative_tolerance * tension_scale_N(mesh, problem_.law->stiffness_scale());
  // Standard gravity, so the limit is the same with gravity on or off.
  const double weight_N = std::accumulate(mass_kg_.begin(), mass_kg_.end(), 0.0) * 9.80665;
  net_force_limit_N_ = parameters_.net_force_tolerance * weight_N;

  // Until the caller places it, the garment lies flat in its layout plane.
  x_.assign(n, Vec3::Zero());
  for (int u = 0; u < mesh.n_unwelded_vertices(); ++u) {
    const Vec2& p = mesh.layout_positions_m[u];
    x_[mesh.welded_index[u]] = Vec3(p.x(), p.y(), 0.0);
  }
  v_.assign(n, Vec3::Zero());
  multiplier_N_.assign(n, 0.0);
  friction_ = FrictionAnchors(problem_.friction_coefficient, problem_.tangential_stiffness_Pa_per_m,
                              rest_vertex_area_m2_);
  force_.assign(n, Vec3::Zero());
  near_.assign(n, NearFaces{});
  asked_at_m_.assign(n, Vec3::Zero());
  clearance_m_.assign(n, 0.0);
  damper_direction_.assign(n, Vec3::Zero());
  if (parameters_.contact_normal_damping_ratio > 0 && problem_.body)
    for (int i = 0; i < n; ++i)
      contact_damper_N_s_per_m_.push_back(contact_damper_N_s_per_m(
          parameters_.contact_normal_damping_ratio,
          problem_.contact_stiffness_Pa_per_m * rest_vertex_area_m2_[i], mass_kg_[i]));
  if (parameters_.placement == Placement::flat_panels)
    flat_start_ = std::make_unique<FlatPanelStart>(problem_, parameters_);
}

MassSpringBackend::~MassSpringBackend() = default;

void MassSpringBackend::set_positions(const std::vector<Vec3>& positions_m) {
  if (static_cast<int>(positions_m.size()) != problem_.mesh->n_vertices)
    throw std::invalid_argument("mass spring: set_positions got " +
                                std::to_string(positions_m.size()) + " positions for " +
                                std::to_string(problem_.mesh->n_vertices) + " vertices");
  x_ = positions_m;
  std::fill(v_.begin(), v_.end(), Vec3::Zero());
  last_ = before_last_ = Settled{};
  // A garment placed anew sticks where it first touches: its anchors are its closest points.
  if (problem_.body) friction_.place(*problem_.body, x_);
}

void MassSpringBackend::predict(double alpha) {
  const double span = last_.alpha - before_last_.alpha;
  if (!std::isfinite(span) || span == 0.0 || alpha == last_.alpha) return;
  // Linear in alpha through the last two stable states: the FE backend's predictor.
  const double ratio = (alpha - last_.alpha) / span;
  for (std::size_t i = 0; i < x_.size(); ++i) {
    x_[i] = last_.x[i] + ratio * (last_.x[i] - before_last_.x[i]);
    multiplier_N_[i] =
        std::max(0.0, last_.multiplier_N[i] +
                          ratio * (last_.multiplier_N[i] - before_last_.multiplier_N[i]));
  }
}

Vec3 MassSpringBackend::contact_force_N(std::size_t i, const Vec3& x, bool* slipping) const {
  const double penalty_N_per_m = problem_.contact_stiffness_Pa_per_m * rest_vertex_area_m2_[i];
  // lambda = m - k A g is zero for g > m / (k A), and g >= g_asked - |x - x_asked| (a distance
  // changes no faster than the point moves). Half of that margin is used: a smooth contact
  // surface's field (docs/bodies.md) is a distance only to within its blending.
  damper_direction_[i] = Vec3::Zero();
  if ((x - asked_at_m_[i]).norm() < 0.5 * (clearance_m_[i] - multiplier_N_[i] / penalty_N_per_m))
    return Vec3::Zero();
  // Without friction the force needs the gap and the normals alone (RigidBody::query_parts).
  QueryParts parts;
  parts.closest_point = parts.normal_derivative = parts.location = friction_.active();
  const SurfacePoint s = problem_.body->query_parts(x, near_[i], parts);
  asked_at_m_[i] = x;
  clearance_m_[i] = s.signed_distance_m;
  const double lambda_N =
      contact_multiplier_N(multiplier_N_[i], penalty_N_per_m, s.signed_distance_m);
  Vec3 f = lambda_N * s.outward_normal;
  if (lambda_N > 0.0) damper_direction_[i] = s.gap_gradient;
  if (friction_.active() && lambda_N > 0.0) {
    const FrictionResponse r =
        friction_.response(int(i), *problem_.body, x, s, lambda_N, Vec3::Zero(), &near_[i]);
    f += r.force_N;
    if (slipping) *slipping = r.slipping;
  }
  return f;
}

int MassSpringBackend::commit_friction_anchors() {
  if (!friction_.active() || !problem_.body) return 0;
  int slipping = 0;
  accepted_friction_N_.assign(x_.size(), Vec3::Zero());
  for (std::size_t i = 0; i < x_.size(); ++i) {
    const SurfacePoint s = problem_.body->query(x_[i]);
    const double lambda_N = contact_multiplier_N(
        multiplier_N_[i], problem_.contact_stiffness_Pa_per_m * rest_vertex_area_m2_[i],
        s.signed_distance_m);
    const FrictionResponse r = friction_.response(int(i), *problem_.body, x_[i], s, lambda_N);
    friction_.commit(int(i), r);
    accepted_friction_N_[i] = r.force_N;
    slipping += r.slipping;
  }
  friction_committed_ = true;
  return slipping;
}

void MassSpringBackend::internal_forces(const std::vector<Vec3>& x,
                                        std::vector<Vec3>& force) const {
  std::fill(force.begin(), force.end(), Vec3::Zero());
  elements_.add_forces(x, force);
  hinges_.add_forces(x, force);
}

double MassSpringBackend::residual_forces(const std::vector<Vec3>& x, bool gravity_on,
                                          std::vector<Vec3>& force) const {
  internal_forces(x, force);
  const std::size_t n = x.size();
  const RigidBody* body = problem_.body;
  const double k = problem_.contact_stiffness_Pa_per_m;
  double largest_squared = 0.0, total_squared = 0.0;
  Vec3 net_N = Vec3::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    if (body && k > 0) force[i] += contact_force_N(i, x[i]);
    if (gravity_on) force[i] += mass_kg_[i] * problem_.gravity_m_per_s2;
    if (constrained_.constrained(i)) constrained_.remove_constrained(i, force[i]);
    const double squared = force[i].squaredNorm();
    largest_squared = std::max(largest_squared, squared);
    total_squared += squared;  // std::max drops NaN; a sum keeps it
    net_N += force[i];
  }
  if (!std::isfinite(total_squared)) return std::numeric_limits<double>::quiet_NaN();
  const double norm_N = parameters_.stop_norm == StopNorm::rms
                            ? std::sqrt(total_squared / double(n))
                            : std::sqrt(largest_squared);
  if (!(net_force_limit_N_ > 0)) return norm_N;
  // norm < tolerance and |net| < limit at once: the net force scaled onto the tolerance.
  return std::max(norm_N, net_N.norm() * tolerance_N_ / net_force_limit_N_);
}

Vec3 MassSpringBackend::net_force_N(const std::vector<Vec3>& force) {
  return std::accumulate(force.begin(), force.end(), Vec3(Vec3::Zero()));
}

void MassSpringBackend::stiffness(const std::vector<Vec3>& x, SparseMatrix& K) const {
  const int n = static_cast<int>(x.size());
  Triplets triplets;
  triplets.reserve(9 * (9 * elements_.size() + 16 * hinges_.size() + x.size()));
  elements_.add_stiffness(x, triplets);
  hinges_.add_stiffness(x, triplets);
  const RigidBody* body = problem_.body;
  const double k = problem_.contact_stiffness_Pa_per_m;
  for (int i = 0; i < n; ++i) {
    // Every vertex gets its diagonal block, in contact or not, so the pattern stays the same.
    Mat3 block = Mat3::Zero();
    if (body && k > 0)
      block = nodal_contact(*body, x[i], multiplier_N_[i], k * rest_vertex_area_m2_[i], true)
                  .stiffness_N_per_m;
    add_block(triplets, i, i, block);
  }
  K.resize(3 * n, 3 * n);
  K.setFromTriplets(triplets.begin(), triplets.end());
  if (constrained_.size() == 0) return;
  // Held directions: K -> P K P + (I - P), P removing them at each held vertex, so an
  // increment has no component along them (the residual has none either).
  Triplets projection, held;
  for (int i = 0; i < n; ++i) {
    Mat3 P = Mat3::Identity();
    if (constrained_.constrained(i))
      for (const Vec3& d : constrained_.directions(i)) P -= d * d.transpose();
    add_block(projection, i, i, P);
    if (constrained_.constrained(i)) add_block(held, i, i, Mat3::Identity() - P);
  }
  SparseMatrix P(3 * n, 3 * n), H(3 * n, 3 * n);
  P.setFromTriplets(projection.begin(), projection.end());
  H.setFromTriplets(held.begin(), held.end());
  K = SparseMatrix(P * K * P) + H;
}

void MassSpringBackend::add_contact_damping(const std::vector<Vec3>& v,
                                            std::vector<Vec3>& force) const {
  for (std::size_t i = 0; i < contact_damper_N_s_per_m_.size(); ++i) {
    const Vec3& n = damper_direction_[i];
    if (n == Vec3::Zero()) continue;
    force[i] -= contact_damper_N_s_per_m_[i] * n.dot(v[i]) * n;
    if (constrained_.constrained(i)) constrained_.remove_constrained(i, force[i]);
  }
}

double MassSpringBackend::rk4_frame(double dt, double c, bool gravity_on, double stop_below_N) {
  const double residual = integrator_.frame(
      x_, v_, mass_kg_, dt, c,
      [&](const std::vector<Vec3>& x, const std::vector<Vec3>& v, std::vector<Vec3>& force) {
        // The residual the stop rule reads is the static one: the damper is added after it.
        const double r = residual_forces(x, gravity_on, force);
        add_contact_damping(v, force);
        return r;
      },
      stop_below_N);
  for (std::size_t i = 0; i < x_.size(); ++i)
    if (constrained_.constrained(i)) constrained_.remove_constrained(i, v_[i]);
  return residual;
}

bool MassSpringBackend::slide_has_ended(double dt_s, double& calm_s) const {
  // The damping force on the garment's mean velocity: a creep's net force (the part of the
  // weight friction does not hold) balances it, and a chattering vertex moves the mean by
  // only its share of the mass.
  Vec3 momentum = Vec3::Zero();
  for (std::size_t i = 0; i < v_.size(); ++i) momentum += mass_kg_[i] * v_[i];
  const double drag_N = parameters_.slide_damping_per_s * momentum.norm();
  calm_s = drag_N < 0.5 * net_force_limit_N_ ? calm_s + dt_s : 0.0;
  return calm_s >= 3.0 / parameters_.slide_damping_per_s;
}

double MassSpringBackend::choose_time_step_s() const {
  if (parameters_.time_step_s > 0) return parameters_.time_step_s;
  // Every particle counts its penalty spring whether it touches the body now or not: it may
  // touch it during the step.
  std::vector<double> stiffness(x_.size(), 0.0);
  elements_.add_stiffness_bounds(x_, stiffness);
  hinges_.add_stiffness_bounds(x_, stiffness);
  if (problem_.body)
    for (std::size_t i = 0; i < x_.size(); ++i) {
      stiffness[i] += problem_.contact_stiffness_Pa_per_m * rest_vertex_area_m2_[i];
      if (friction_.active()) stiffness[i] += friction_.tangential_stiffness_N_per_m(int(i));
    }
  // The contact dampers, if any, may ask for a shorter step than the springs (a damping ratio
  // above about a half of the stiffest vertex's, where the contact spring sets the step).
  return std::min(
      stable_time_step_s(stiffness, mass_kg_, parameters_.time_step_safety),
      damper_time_step_s(contact_damper_N_s_per_m_, mass_kg_, parameters_.time_step_safety));
}

double MassSpringBackend::contact_penetration_m(bool update_multipliers) {
  double penetration_m = 0.0;
  const RigidBody* body = problem_.body;
  const double k = problem_.contact_stiffness_Pa_per_m;
  if (!body || !(k > 0)) return penetration_m;
  for (std::size_t i = 0; i < x_.size(); ++i) {
    const double gap_m = body->query(x_[i]).signed_distance_m;
    const double lambda_N =
        contact_multiplier_N(multiplier_N_[i], k * rest_vertex_area_m2_[i], gap_m);
    if (update_multipliers) multiplier_N_[i] = lambda_N;
    if (lambda_N > 0.0) penetration_m = std::max(penetration_m, -gap_m);
  }
  return penetration_m;
}

StepReport MassSpringBackend::solve(const LoadStep& step) {
  const auto start = std::chrono::steady_clock::now();
  // The process's CPU time too: on a shared machine the wall time says little.
  const std::clock_t cpu_start = std::clock();
  friction_committed_ = false;
  std::string flat_start_detail;
  int flat_start_frames = 0;
  if (flat_start_) {
    // The paper's start (Section 4.3): the panels close their seams round the cylinder, then
    // the welded garment settles below. Replaces whatever set_positions gave.
    const FlatPanelResult flat = flat_start_->run(step);
    flat_start_.reset();
    x_ = flat.welded_positions_m;
    flat_start_frames = flat.frames;
    std::ostringstream detail;
    detail << "flat-panel start: seams closed (largest gap " << flat.largest_seam_gap_m << " m < "
           << flat.closed_below_m << " m) after " << flat.frames << " frames, " << flat.wall_seconds
           << " s; then ";
    flat_start_detail = detail.str();
    if (problem_.body) friction_.place(*problem_.body, x_);
  }
  if (problem_.body && friction_.active() && !friction_.placed())
    friction_.place(*problem_.body, x_);

  // The body may have changed since the last step (a morph, a growth): nothing of its last
  // queries is known to hold.
  std::fill(clearance_m_.begin(), clearance_m_.end(), 0.0);
  const bool implicit = parameters_.integrator == Integrator::implicit;
  if (implicit) predict(step.alpha);
  time_step_s_ = choose_time_step_s();
  damping_per_s_ = parameters_.damping_per_s > 0
                       ? parameters_.damping_per_s
                       : critical_damping_per_s(problem_.law->stiffness_scale(),
                                                problem_.fabric->areal_density_kg_per_m2, size_m_);
  const std::vector<Vec3> start_x = x_;
  // Particles that run further than this from where the step began have diverged.
  const double runaway_m = 10.0 * size_m_;
  std::fill(v_.begin(), v_.end(), Vec3::Zero());

  ResidualHistory history(parameters_.stall_window_frames, parameters_.stall_fall);
  // The residual history follows the message on the lines below it.
  auto fail = [&](const std::string& what, int frame, double residual, bool with_history) {
    std::ostringstream message;
    message << "mass spring: " << step_name(step) << " " << what << " at frame " << frame
            << " (residual " << residual << " N, tolerance " << tolerance_N_ << " N, time step "
            << time_step_s_ << " s)";
    if (with_history) {
      // Where the residual sits and whether the garment as a whole is still pushed (a slide).
      residual_forces(x_, step.gravity_on, force_);
      message << "; " << text(locate_residual(x_, force_, problem_.body)) << "; " << history.text();
    }
    return SolverError(message.str());
  };

  int frame = 0, halvings = 0;
  double residual = 0.0;
  // Slide damping: the step's first frames, until the slide has ended, at the lower damping.
  bool sliding = !implicit && parameters_.slide_damping_per_s > 0;
  int slide_frames = 0;
  double calm_s = 0.0;
  // Damped RK4 from the current state until the stop rule holds; `frame` counts on over the
  // settles of one step (the frame limit is the step's). A stalled window halves the time
  // step (residual_history.h) until the halvings run out.
  std::string newton_history;
  // The implicit route: Newton from the current state to the same stop rule; `frame` counts
  // its factorisations.
  auto settle_implicit = [&]() {
    const StaticNewton::Result r = newton_.solve(
        x_, mass_kg_,
        [&](const std::vector<Vec3>& x, std::vector<Vec3>& force) {
          return residual_forces(x, step.gravity_on, force);
        },
        [&](const std::vector<Vec3>& x, SparseMatrix& K) { stiffness(x, K); }, tolerance_N_,
        1.0 / damping_per_s_, parameters_.maximum_newton_iterations - frame);
    frame += r.iterations;
    residual = r.residual_N;
    newton_history += (newton_history.empty() ? "" : "; ") + r.history;
    if (r.converged) return;
    std::ostringstream what;
    what << "did not reach equilibrium (implicit integrator, " << frame
         << " Newton iterations, Mass spring/Maximum Newton iterations "
         << parameters_.maximum_newton_iterations << "); " << newton_history;
    throw fail(what.str(), frame, residual, false);
  };
  auto settle = [&]() {
    if (implicit) return settle_implicit();
    history.restart();
    for (;;) {
      // The paper's quasi-static start (Section 4.3): velocity ignored, reset every frame.
      const bool quasi_static = frame < parameters_.quasi_static_frames;
      if (quasi_static) std::fill(v_.begin(), v_.end(), Vec3::Zero());
      const double c = quasi_static ? 0.0
                       : sliding    ? parameters_.slide_damping_per_s
                                    : damping_per_s_;
      // While the garment slides the stop rule is not read: at the slide's lower damping a
      // creep shows a smaller net force (massspring_parameters.h).
      residual = rk4_frame(time_step_s_, c, step.gravity_on,
                           sliding ? -std::numeric_limits<double>::infinity() : tolerance_N_);
      if (!std::isfinite(residual))
        throw fail("diverged (non-finite force; try a smaller Mass spring/Time step)", frame,
                   residual, false);
      if (sliding) {
        if (!quasi_static && slide_has_ended(time_step_s_, calm_s)) {
          sliding = false;
          slide_frames = frame + 1;
          history.restart();
        }
      } else if (residual < tolerance_N_) {
        return;  // rk4_frame left the stable state untouched
      } else if (history.record(frame, residual, time_step_s_)) {
        if (halvings == parameters_.stall_halvings)
          throw fail(
              "stalled (the residual did not fall below Mass spring/Stall residual fall "
              "times its earlier windows' after " +
                  std::to_string(halvings) + " time step halvings)",
              frame, residual, true);
        time_step_s_ *= 0.5;
        ++halvings;
        history.restart();
      }
      ++frame;
      if (parameters_.time_step_update_frames > 0 && parameters_.time_step_s == 0 &&
          frame % parameters_.time_step_update_frames == 0)
        time_step_s_ = std::ldexp(choose_time_step_s(), -halvings);
      throw_if_interrupted(interruption_signal(),
                           "during " + step_name(step) + " at frame " + std::to_string(frame));
      if (frame % 64 == 0)
        for (std::size_t i = 0; i < x_.size(); ++i)
          if (!((x_[i] - start_x[i]).norm() < runaway_m))
            throw fail("diverged (vertex " + std::to_string(i) + " ran away)", frame, residual,
                       false);
      if (frame >= parameters_.maximum_frames) {
        residual = residual_forces(x_, step.gravity_on, force_);
        if (!sliding && residual < tolerance_N_) return;
        throw fail(sliding ? "was still sliding (Mass spring/Slide damping) at Mass "
                             "spring/Maximum frames"
                           : "did not reach equilibrium within Mass spring/Maximum frames",
                   frame, residual, true);
      }
    }
  };
  // Uzawa's iteration on the contact multipliers (penalty_contact.h): each settled state
  // hands its contact forces to the next settle as multipliers, until no vertex sits deeper
  // than the gap tolerance; the state settles once more after the last update, which moves
  // every force by kA g. The multipliers carry over to the next load step as its start.
  const bool augmented = parameters_.contact_updates > 0;
  int updates = 0;
  for (;;) {
    settle();
    if (!augmented) break;
    double penetration_m = contact_penetration_m(true);
    if (penetration_m <= parameters_.gap_tolerance_m) {
      settle();
      // The settle after the last update moves each vertex by up to its kA g; the stable state
      // handed on must itself keep every vertex within the gap tolerance (a tube sliding on a
      // cone under friction has been seen 1.6e-8 m deep there), else the updates go on.
      penetration_m = contact_penetration_m(false);
      if (penetration_m <= parameters_.gap_tolerance_m) break;
    }
    if (updates == parameters_.contact_updates) {
      std::ostringstream what;
      what << "kept a penetration of " << penetration_m << " m (Mass spring/Gap tolerance "
           << parameters_.gap_tolerance_m << " m) after " << updates
           << " contact multiplier updates";
      throw fail(what.str(), frame, residual, false);
    }
    ++updates;
  }
  const double penetration_m = contact_penetration_m(false);
  if (implicit) {
    before_last_ = std::move(last_);
    last_ = Settled{step.alpha, x_, multiplier_N_};
  }
  // The net force as the stop rule saw it: friction from the anchors the step solved with
  // (committing them moves them onto the state and takes their force away).
  residual_forces(x_, step.gravity_on, force_);
  const Vec3 net_N = net_force_N(force_);
  const int slipping = commit_friction_anchors();

  StepReport report;
  report.iterations = flat_start_frames + frame;
  report.residual_N = residual;
  report.tolerance_N = tolerance_N_;
  report.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::ostringstream detail;
  detail << "mass spring: " << step_name(step) << " " << flat_start_detail;
  if (parameters_.slide_damping_per_s > 0 && !implicit)
    detail << "slid at damping " << parameters_.slide_damping_per_s << " 1/s for " << slide_frames
           << " frames, ";
  detail << "stable after ";
  if (implicit)
    detail << frame << " Newton iterations (implicit, " << updates
           << " contact multiplier updates), first pseudo time step " << 1.0 / damping_per_s_
           << " s, residual " << residual << " N < ";
  else
    detail << frame << " frames (" << std::min(frame, parameters_.quasi_static_frames)
           << " quasi-static, " << updates << " contact multiplier updates, " << halvings
           << " time step halvings), dt " << time_step_s_ << " s, damping " << damping_per_s_
           << " 1/s, residual " << residual << " N < ";
  detail << tolerance_N_ << " N" << (parameters_.stop_norm == StopNorm::rms ? " (rms)" : "")
         << ", net force on the garment " << net_N.norm() << " N (" << net_N.x() << ", "
         << net_N.y() << ", " << net_N.z() << ")";
  if (net_force_limit_N_ > 0) detail << " < " << net_force_limit_N_ << " N";
  // How many vertices the committed friction anchors let slide (Coulomb cone reached).
  if (friction_.active()) detail << ", " << slipping << " vertices slipping";
  detail << ", largest penetration " << penetration_m << " m, " << report.wall_seconds << " s ("
         << double(std::clock() - cpu_start) / CLOCKS_PER_SEC << " s CPU)";
  if (halvings > 0) detail << "; " << history.text();
  report.detail = detail.str();
  return report;
}

SurfaceState MassSpringBackend::state() const {
  SurfaceState s;
  s.positions_m = x_;
  s.internal_force_N.assign(x_.size(), Vec3::Zero());
  internal_forces(x_, s.internal_force_N);
  if (problem_.body) {
    apply_penalty_contact(*problem_.body, problem_.contact_stiffness_Pa_per_m, rest_vertex_area_m2_,
                          s, multiplier_N_);
    // The friction force joins the normal one, so the extractor reads it as friction traction:
    // as accepted, or (a step that failed) from the anchors the step was solving with.
    if (friction_.active())
      for (std::size_t i = 0; i < x_.size(); ++i)
        if (s.in_contact[i])
          s.contact_force_N[i] = friction_committed_
                                     ? Vec3(s.contact_force_N[i] + accepted_friction_N_[i])
                                     : contact_force_N(i, x_[i]);
  } else {
    s.contact_force_N.assign(x_.size(), Vec3::Zero());
    s.in_contact.assign(x_.size(), 0);
    s.gap_m.assign(x_.size(), 0.0);
  }
  return s;
}

}  // namespace tightfit
