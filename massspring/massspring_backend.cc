#include "massspring/massspring_backend.h"
#include "core/interruption.h"
#include "core/load_step_report.h"

#include "bodies/rigid_body.h"
#include "contact/body_query_pool.h"
#include "contact/nodal_contact.h"
#include "contact/penalty_contact.h"
#include "contact/residual_location.h"
#include "core/residual_history.h"
#include "core/step_report.h"
#include "core/tension_scale.h"
#include "massspring/flat_panel_start.h"
#include "massspring/lumped_mass.h"
#include "massspring/positive_part.h"
#include "massspring/stable_time_step.h"

#include <algorithm>
#include <cmath>
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
  inertia_kg_ = mass_kg_;
  rest_vertex_area_m2_ = rest_vertex_areas_m2(mesh);
  constrained_ = ConstrainedDirections(problem_.constraints, n);
  held_turn_ = HeldTurn(problem_.constraints, n);
  size_m_ = std::sqrt(rest_area(mesh));
  // Stop rule: a force relative to the tension scale Y h^2 / L (core/garment.h says why).
  tolerance_N_ = relative_threshold_N(parameters_.stop,
                                      tension_scale_N(mesh, problem_.law->stiffness_scale()));
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
  contact_N_.assign(n, Vec3::Zero());
  pool_ = body_query_pool(problem_.body, problem_.threads);
  near_.assign(n, NearFaces{});
  asked_at_m_.assign(n, Vec3::Zero());
  clearance_m_.assign(n, 0.0);
  damper_direction_.assign(n, Vec3::Zero());
  multiplier_change_N_.assign(n, 0.0);
  normal_force_N_.assign(n, 0.0);
  carry_contact_ = problem_.body && problem_.body->costly_queries() && !friction_.active();
  carried_contact_.assign(n, CarriedContact{});
  if (parameters_.contact_normal_damping_ratio > 0 && problem_.body)
    for (int i = 0; i < n; ++i)
      contact_damper_N_s_per_m_.push_back(contact_damper_N_s_per_m(
          parameters_.contact_normal_damping_ratio,
          problem_.contact_stiffness_Pa_per_m * rest_vertex_area_m2_[i], mass_kg_[i]));
  stick_normal_.assign(n, Vec3::Zero());
  if (parameters_.contact_stick_damping_ratio > 0 && friction_.active() && problem_.body)
    for (int i = 0; i < n; ++i)
      stick_damper_N_s_per_m_.push_back(
          contact_damper_N_s_per_m(parameters_.contact_stick_damping_ratio,
                                   friction_.tangential_stiffness_N_per_m(i), mass_kg_[i]));
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
  history_.forget();
  // A garment placed anew sticks where it first touches: its anchors are its closest points.
  if (problem_.body) friction_.place(*problem_.body, x_);
}

void MassSpringBackend::predict(double alpha) {
  history_.predict(
      alpha, multiplier_N_,
      [&](double ratio, const std::vector<Vec3>& last, const std::vector<Vec3>& before) {
        for (std::size_t i = 0; i < x_.size(); ++i) x_[i] = last[i] + ratio * (last[i] - before[i]);
      });
}

void MassSpringBackend::record_settled(double alpha, bool in_contact) {
  history_.record(alpha, in_contact, x_, multiplier_N_);
}

Vec3 MassSpringBackend::contact_force_N(std::size_t i, const Vec3& x, bool* slipping,
                                        bool carried) const {
  const double penalty_N_per_m = problem_.contact_stiffness_Pa_per_m * rest_vertex_area_m2_[i];
  // lambda = m - k A g is zero for g > m / (k A), and g >= g_asked - |x - x_asked| (a distance
  // changes no faster than the point moves). Half of that margin is used: a smooth contact
  // surface's field (docs/bodies.md) is a distance only to within its blending.
  damper_direction_[i] = Vec3::Zero();
  stick_normal_[i] = Vec3::Zero();
  // Out of reach the force is zero, and an update would take the multiplier to zero.
  multiplier_change_N_[i] = multiplier_N_[i];
  normal_force_N_[i] = 0.0;
  CarriedContact& carry = carried_contact_[i];
  if (!carried) carry.valid = false;
  if ((x - asked_at_m_[i]).norm() < 0.5 * (clearance_m_[i] - multiplier_N_[i] / penalty_N_per_m))
    return Vec3::Zero();
  SurfacePoint s;
  if (carried && carry.valid) {
    // The first stage's answer carried to x to first order (massspring_backend.h).
    const Vec3 step = x - carry.x0_m;
    s.signed_distance_m = carry.gap_m + carry.gap_gradient.dot(step);
    s.gap_gradient = carry.gap_gradient;
    s.outward_normal = (carry.normal + carry.normal_derivative_per_m * step).normalized();
  } else {
    // The force needs the gap and the normals alone (RigidBody::query_parts); friction and the
    // carried stages need dn/dx too. Friction's closest point and location would only place a
    // slipping anchor, which a frame does not keep (commit_friction_anchors places them).
    QueryParts parts;
    parts.closest_point = parts.location = false;
    parts.normal_derivative = friction_.active() || carry_contact_;
    s = problem_.body->query_parts(x, near_[i], parts);
    asked_at_m_[i] = x;
    clearance_m_[i] = s.signed_distance_m;
    if (carry_contact_)
      carry = {true,
               x,
               s.gap_gradient,
               s.outward_normal,
               s.signed_distance_m,
               s.normal_derivative_per_m};
  }
  const double lambda_N =
      contact_multiplier_N(multiplier_N_[i], penalty_N_per_m, s.signed_distance_m);
  multiplier_change_N_[i] = std::abs(lambda_N - multiplier_N_[i]);
  normal_force_N_[i] = lambda_N;
  Vec3 f = lambda_N * s.outward_normal;
  if (lambda_N > 0.0) damper_direction_[i] = s.gap_gradient;
  if (friction_.active() && lambda_N > 0.0) {
    const FrictionResponse r =
        friction_.response(int(i), *problem_.body, x, s, lambda_N, Vec3::Zero(), &near_[i], false);
    f += r.force_N;
    if (slipping) *slipping = r.slipping;
    if (!r.slipping && !stick_damper_N_s_per_m_.empty()) stick_normal_[i] = s.outward_normal;
  }
  return f;
}

void MassSpringBackend::contact_forces(const std::vector<Vec3>& x, bool carried) const {
  for_each_part(pool_.get(), x.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
      contact_N_[i] = contact_force_N(i, x[i], nullptr, carried);
  });
}

int MassSpringBackend::commit_friction_anchors() {
  if (!friction_.active() || !problem_.body) return 0;
  accepted_friction_N_.assign(x_.size(), Vec3::Zero());
  std::vector<char> slips(x_.size(), 0);
  // Each vertex commits its own anchor (FrictionAnchors::commit), read by no other vertex.
  for_each_part(pool_.get(), x_.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const SurfacePoint s = problem_.body->query(x_[i]);
      const double lambda_N = contact_multiplier_N(
          multiplier_N_[i], problem_.contact_stiffness_Pa_per_m * rest_vertex_area_m2_[i],
          s.signed_distance_m);
      const FrictionResponse r = friction_.response(int(i), *problem_.body, x_[i], s, lambda_N);
      friction_.commit(int(i), r);
      accepted_friction_N_[i] = r.force_N;
      slips[i] = r.slipping;
    }
  });
  friction_committed_ = true;
  return int(std::count(slips.begin(), slips.end(), 1));
}

void MassSpringBackend::internal_forces(const std::vector<Vec3>& x,
                                        std::vector<Vec3>& force) const {
  std::fill(force.begin(), force.end(), Vec3::Zero());
  elements_.add_forces(x, force);
  hinges_.add_forces(x, force);
}

double MassSpringBackend::residual_forces(const std::vector<Vec3>& x, bool gravity_on,
                                          std::vector<Vec3>& force, bool carried) const {
  internal_forces(x, force);
  const std::size_t n = x.size();
  const RigidBody* body = problem_.body;
  const double k = problem_.contact_stiffness_Pa_per_m;
  ResidualSize size;  // the stop rule's size of the field (core/load_step.h)
  Vec3 net_N = Vec3::Zero();
  largest_multiplier_change_N_ = 0.0;
  double contact_load_N = 0.0;  // the normal contact forces' sum, over n_in_contact vertices
  long n_in_contact = 0;
  if (body && k > 0) contact_forces(x, carried);
  for (std::size_t i = 0; i < n; ++i) {
    if (body && k > 0) {
      force[i] += contact_N_[i];
      largest_multiplier_change_N_ =
          std::max(largest_multiplier_change_N_, multiplier_change_N_[i]);
      contact_load_N += normal_force_N_[i];
      n_in_contact += normal_force_N_[i] > 0.0;
    }
    if (gravity_on) force[i] += mass_kg_[i] * problem_.gravity_m_per_s2;
    if (constrained_.constrained(i)) constrained_.remove_constrained(i, force[i]);
    size.add(force[i].norm());
    net_N += force[i];
  }
  if (held_turn_.active()) {
    // The held turn's reaction (core/held_turn.h) is part of the residual the rule reads.
    held_turn_.remove_from_forces(x, mass_kg_, force);
    size = ResidualSize();
    for (const Vec3& f : force) size.add(f.norm());
  }
  // The rule at this state's contact load (core/load_step.h), which the checks compare the size
  // with (settle_stop_N).
  stop_threshold_N_ = parameters_.stop.threshold_N(tolerance_N_, contact_load_N, n_in_contact);
  const double norm_N = size.read(parameters_.stop.norm, double(n));
  residual_norm_N_ = norm_N;
  residual_net_N_ = net_N.norm();
  if (std::isnan(norm_N)) return norm_N;  // a force not finite
  if (!(net_force_limit_N_ > 0)) return norm_N;
  // norm < threshold and |net| < limit at once: the net force scaled onto the tension-scale
  // rule. Against the contact-load threshold the net force's limit tightens in the same ratio
  // (net_force_limit_at_N): the net force is the residuals' sum, and over the contact load it is
  // the mean pressure's error too (a light sheet lying on a plane).
  return std::max(norm_N, net_N.norm() * tolerance_N_ / net_force_limit_N_);
}

double MassSpringBackend::net_force_limit_at_N(double threshold_N) const {
  return net_force_limit_N_ * threshold_N / tolerance_N_;
}

Vec3 MassSpringBackend::net_force_N(const std::vector<Vec3>& force) {
  return std::accumulate(force.begin(), force.end(), Vec3(Vec3::Zero()));
}

void MassSpringBackend::stiffness(const std::vector<Vec3>& x, SparseMatrix& K) const {
  const int n = static_cast<int>(x.size());
  Triplets triplets;
  triplets.reserve(9 * (9 * elements_.size() + 16 * hinges_.size() + x.size()));
  elements_.add_stiffness(x, triplets, projected_tangent());
  hinges_.add_stiffness(x, triplets);
  const RigidBody* body = problem_.body;
  const double k = problem_.contact_stiffness_Pa_per_m;
  linearised_contact_.assign(body && k > 0 ? n : 0, LinearisedContact{});
  for (int i = 0; i < n; ++i) {
    // Every vertex gets its diagonal block, in contact or not, so the pattern stays the same.
    Mat3 block = Mat3::Zero();
    if (body && k > 0) {
      LinearisedContact& c = linearised_contact_[i];
      c.surface = body->query(x[i]);
      const double penalty_N_per_m = k * rest_vertex_area_m2_[i];
      const double lambda_N =
          contact_multiplier_N(multiplier_N_[i], penalty_N_per_m, c.surface.signed_distance_m);
      c.active = lambda_N > 0.0;
      if (c.active) {
        const NodalContact contact =
            contact_with_multiplier(c.surface, lambda_N, penalty_N_per_m, true);
        block = contact.stiffness_N_per_m;
        Vec3 force_N = contact.force_N;
        if (friction_.active()) {
          // The friction spring's tangent from the return mapping (contact/coulomb_friction.h),
          // its symmetric part (CHOLMOD's LL^T): without it a stuck vertex's tangential
          // stiffness, as large as the contact spring's, is missing from the system and the
          // Newton steps overshoot across the body.
          const FrictionResponse r = friction_.response(i, *body, x[i], c.surface, lambda_N,
                                                        -penalty_N_per_m * c.surface.gap_gradient);
          block += 0.5 * (r.stiffness_N_per_m + r.stiffness_N_per_m.transpose());
          force_N += r.force_N;
        }
        // The body's curvature (-lambda dn/dx) and a slip's normal-tangential coupling make
        // the block indefinite: its positive part (positive_part.h).
        block = projected_block(block);
        c.force_N = held_projection(i) * force_N;
      }
      c.block = held_projection(i) * block * held_projection(i);
    }
    add_block(triplets, i, i, block);
  }
  K.resize(3 * n, 3 * n);
  K.setFromTriplets(triplets.begin(), triplets.end());
  if (constrained_.size() == 0) return;
  // Held directions: K -> P K P + (I - P), P removing them at each held vertex, so an
  // increment has no component along them (the residual has none either).
  Triplets projection, held;
  for (int i = 0; i < n; ++i) {
    const Mat3 P = held_projection(i);
    add_block(projection, i, i, P);
    if (constrained_.constrained(i)) add_block(held, i, i, Mat3::Identity() - P);
  }
  SparseMatrix P(3 * n, 3 * n), H(3 * n, 3 * n);
  P.setFromTriplets(projection.begin(), projection.end());
  H.setFromTriplets(held.begin(), held.end());
  K = SparseMatrix(P * K * P) + H;
}

Mat3 MassSpringBackend::held_projection(int i) const {
  Mat3 P = Mat3::Identity();
  if (constrained_.constrained(i))
    for (const Vec3& d : constrained_.directions(i)) P -= d * d.transpose();
  return P;
}

bool MassSpringBackend::predict_contact_set(const Eigen::VectorXd& dx, SparseMatrix& A,
                                            Eigen::VectorXd& rhs) const {
  const double k = problem_.contact_stiffness_Pa_per_m;
  bool changed = false;
  for (std::size_t i = 0; i < linearised_contact_.size(); ++i) {
    LinearisedContact& c = linearised_contact_[i];
    const SurfacePoint& s = c.surface;
    const double penalty_N_per_m = k * rest_vertex_area_m2_[i];
    // The gap the increment predicts, to first order.
    const double gap_m = s.signed_distance_m + s.gap_gradient.dot(dx.segment<3>(3 * i));
    const bool active = contact_multiplier_N(multiplier_N_[i], penalty_N_per_m, gap_m) > 0.0;
    if (active == c.active) continue;
    changed = true;
    const Mat3 P = held_projection(int(i));
    Mat3 block;
    Vec3 force;
    if (active) {
      // Closes: the force (lambda_bar - kA g - kA grad g . dx) n, linearised at x although it is
      // zero there (penalty_contact.h), the curvature's term left out (lambda is zero at x).
      const NodalContact contact = contact_with_multiplier(
          s, multiplier_N_[i] - penalty_N_per_m * s.signed_distance_m, penalty_N_per_m, true);
      block = P * projected_block(contact.stiffness_N_per_m) * P;
      force = P * contact.force_N;
    } else {
      // Opens: the force and stiffness it has in the system leave it.
      block = -c.block;
      force = -c.force_N;
    }
    for (int r = 0; r < 3; ++r)
      for (int col = 0; col < 3; ++col) A.coeffRef(3 * i + r, 3 * i + col) += block(r, col);
    rhs.segment<3>(3 * i) += force;
    c.active = active;
    c.block = active ? block : Mat3::Zero();
    c.force_N = active ? force : Vec3::Zero();
  }
  return changed;
}

bool MassSpringBackend::projected_tangent() const {
  return parameters_.implicit_tangent == ImplicitTangent::projected ||
         (parameters_.implicit_tangent == ImplicitTangent::automatic && friction_.active());
}

Mat3 MassSpringBackend::projected_block(const Mat3& block) const {
  if (!projected_tangent()) return block;
  return positive_part(block);
}

bool MassSpringBackend::rk4_assists_newton() const {
  // On a mesh body without friction (the queries carried over RK4's stages): there the
  // approach is where Newton is slow, and the smooth surface's jumps where it stalls.
  return parameters_.integrator == Integrator::implicit &&
         parameters_.implicit_approach_factor > 0 && carry_contact_;
}

StaticNewton::Hooks MassSpringBackend::newton_hooks() const {
  StaticNewton::Hooks hooks;
  hooks.remember_refusals = projected_tangent();
  if (held_turn_.active())
    hooks.held_mode = [this](const std::vector<Vec3>& x, Eigen::VectorXd& w) {
      held_turn_mode(x, w);
    };
  if (problem_.body && problem_.contact_stiffness_Pa_per_m > 0 &&
      parameters_.contact_set_predictions > 0) {
    hooks.contact_set = [this](const Eigen::VectorXd& dx, SparseMatrix& A, Eigen::VectorXd& rhs) {
      return predict_contact_set(dx, A, rhs);
    };
    hooks.contact_set_solves = parameters_.contact_set_predictions;
  }
  return hooks;
}

void MassSpringBackend::held_turn_mode(const std::vector<Vec3>& x, Eigen::VectorXd& w) const {
  // w_i = m_i a x (x_i - c), c the centre of mass (core/held_turn.h): the increments keep the
  // garment's mean turn about the held axis, as RK4's velocities do.
  Vec3 centre = Vec3::Zero();
  HeldTurn::centre_of_mass(x, mass_kg_, centre);
  w.resize(3 * Eigen::Index(x.size()));
  for (std::size_t i = 0; i < x.size(); ++i)
    w.segment<3>(3 * i) = mass_kg_[i] * held_turn_.axis().cross(x[i] - centre);
}

void MassSpringBackend::add_contact_damping(const std::vector<Vec3>& v,
                                            std::vector<Vec3>& force) const {
  // A sticking vertex's friction spring, across the normal (massspring_parameters.h).
  for (std::size_t i = 0; i < stick_damper_N_s_per_m_.size(); ++i) {
    const Vec3& n = stick_normal_[i];
    if (n == Vec3::Zero()) continue;
    force[i] -= stick_damper_N_s_per_m_[i] * (v[i] - n.dot(v[i]) * n);
    if (constrained_.constrained(i)) constrained_.remove_constrained(i, force[i]);
  }
  for (std::size_t i = 0; i < contact_damper_N_s_per_m_.size(); ++i) {
    const Vec3& n = damper_direction_[i];
    if (n == Vec3::Zero()) continue;
    force[i] -= contact_damper_N_s_per_m_[i] * n.dot(v[i]) * n;
    if (constrained_.constrained(i)) constrained_.remove_constrained(i, force[i]);
  }
}

double MassSpringBackend::rk4_frame(double dt, double c, bool gravity_on, bool may_stop) {
  int stage = 0;
  const double residual = integrator_.frame(
      x_, v_, inertia_kg_, dt, c,
      [&](const std::vector<Vec3>& x, const std::vector<Vec3>& v, std::vector<Vec3>& force) {
        // The residual the stop rule reads is the static one: the damper is added after it.
        // The first stage queries the body; the later ones may carry its answers.
        const bool first = stage++ == 0;
        const double r = residual_forces(x, gravity_on, force, carry_contact_ && !first);
        if (first) {
          frame_norm_N_ = residual_norm_N_;
          frame_net_N_ = residual_net_N_;
          frame_threshold_N_ = stop_threshold_N_;
          frame_stop_N_ = settle_stop_N();
        }
        add_contact_damping(v, force);
        return r;
      },
      [&](double residual_N) { return may_stop && residual_N < frame_stop_N_; });
  for (std::size_t i = 0; i < x_.size(); ++i)
    if (constrained_.constrained(i)) constrained_.remove_constrained(i, v_[i]);
  held_turn_.remove_from_velocities(x_, mass_kg_, v_);
  return residual;
}

Vec3 MassSpringBackend::momentum() const {
  Vec3 sum = Vec3::Zero();
  for (std::size_t i = 0; i < v_.size(); ++i) sum += mass_kg_[i] * v_[i];
  return sum;
}

bool MassSpringBackend::slide_has_ended(double dt_s, double c, double& calm_s) const {
  // The damping force on the garment's mean velocity: a creep's net force (the part of the
  // weight friction does not hold) balances it, and a chattering vertex moves the mean by
  // only its share of the mass.
  const double drag_N = c * momentum().norm();
  calm_s = drag_N < 0.5 * net_force_limit_N_ ? calm_s + dt_s : 0.0;
  return calm_s >= 3.0 / c;
}

bool MassSpringBackend::creeping(double c) const {
  // Each vertex balanced (the norm met) while the garment as a whole is not, and moves at the
  // speed its damping lets the unbalanced force drive it.
  return frame_norm_N_ < frame_stop_N_ &&
         frame_net_N_ >= net_force_limit_at_N(frame_threshold_N_) &&
         c * momentum().norm() >= 0.5 * frame_net_N_;
}

double MassSpringBackend::choose_time_step_s() {
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
  // Mass scaling: the particles stiffer for their mass than the ratio times the median one
  // move as if heavier, so that the time step follows the typical particle.
  inertia_kg_ = parameters_.mass_scaling_ratio > 0
                    ? mass_scaled_kg(stiffness, mass_kg_, parameters_.mass_scaling_ratio)
                    : mass_kg_;
  // The contact dampers, if any, may ask for a shorter step than the springs (a damping ratio
  // above about a half of the stiffest vertex's, where the contact spring sets the step).
  return std::min(
      stable_time_step_s(stiffness, inertia_kg_, parameters_.time_step_safety),
      std::min(
          damper_time_step_s(contact_damper_N_s_per_m_, inertia_kg_, parameters_.time_step_safety),
          damper_time_step_s(stick_damper_N_s_per_m_, inertia_kg_, parameters_.time_step_safety)));
}

double MassSpringBackend::contact_penetration_m(bool update_multipliers, int* in_contact) {
  double penetration_m = 0.0;
  if (in_contact) *in_contact = 0;
  const RigidBody* body = problem_.body;
  const double k = problem_.contact_stiffness_Pa_per_m;
  if (!body || !(k > 0)) return penetration_m;
  std::vector<double> gaps_m(x_.size());
  for_each_part(pool_.get(), x_.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) gaps_m[i] = body->query(x_[i]).signed_distance_m;
  });
  for (std::size_t i = 0; i < x_.size(); ++i) {
    const double gap_m = gaps_m[i];
    const double lambda_N =
        contact_multiplier_N(multiplier_N_[i], k * rest_vertex_area_m2_[i], gap_m);
    if (update_multipliers) multiplier_N_[i] = lambda_N;
    if (lambda_N > 0.0) {
      penetration_m = std::max(penetration_m, -gap_m);
      if (in_contact) ++*in_contact;
    }
  }
  return penetration_m;
}

double MassSpringBackend::settle_stop_N() const {
  if (approaching_) return parameters_.implicit_approach_factor * stop_threshold_N_;
  if (final_settle_next_) return stop_threshold_N_;
  return std::max(stop_threshold_N_,
                  parameters_.inexact_round_fraction * largest_multiplier_change_N_);
}

// What the settles of one load step share: the frames are counted over the step (the frame
// limit is the step's), the time step keeps its halvings, the slide ends once.
struct MassSpringBackend::StepRun {
  StepRun(const MassSpringParameters& p)
      : history(p.stall_window_frames, p.stall_fall),
        sliding(p.integrator == Integrator::rk4 && p.slide_damping_per_s > 0),
        slide_per_s(p.slide_damping_per_s),
        may_creep_slide(p.integrator == Integrator::rk4 && !sliding &&
                        p.creep_slide_damping_per_s > 0) {}
  StepClock clock;
  LoadStep step;
  std::vector<Vec3> start_x;
  double runaway_m = 0.0;  // particles further than this from start_x have diverged
  // Halvings of the time step in force (the current round's) and over the whole step.
  int frame = 0, halvings = 0, step_halvings = 0;
  double residual_N = 0.0;
  ResidualHistory history;
  // Slide damping: the step's first frames, until the slide has ended, at the lower damping.
  bool sliding;
  double slide_per_s;  // the slide's damping, 1/s
  // Creep slide damping: a stall in a creep may still start a slide (once a step).
  bool may_creep_slide;
  int slide_start_frame = 0, slide_frames = 0;
  double calm_s = 0.0;
  std::string newton_history;  // implicit: every settle's iterations
  // Implicit: Newton iterations (frame counts them and any RK4 frames), whether the approach
  // by RK4 has run, and the settles RK4 finished after Newton stalled.
  int newton_iterations = 0, newton_stalls = 0;
  bool approached = false;
};

SolverError MassSpringBackend::step_failure(StopReason reason, const std::string& what,
                                            bool with_history) const {
  const StepRun& run = *run_;
  std::ostringstream details;
  details << "time step " << time_step_s_ << " s";
  if (with_history) {
    // Where the residual sits and whether the garment as a whole is still pushed (a slide).
    residual_forces(x_, run.step.gravity_on, force_);
    details << "; " << text(locate_residual(x_, force_, problem_.body)) << "; "
            << run.history.text();
  }
  return load_step_failure(reason, "mass spring", run.step,
                           what + " at frame " + std::to_string(run.frame), run.residual_N,
                           stop_threshold_N_, details.str());
}

void MassSpringBackend::run_flat_start(const LoadStep& step, StepReport& report) {
  if (!flat_start_) return;
  // The paper's start (Section 4.3): the panels close their seams round the cylinder, then
  // the welded garment settles below. Replaces whatever set_positions gave.
  const FlatPanelResult flat = flat_start_->run(step);
  flat_start_.reset();
  x_ = flat.welded_positions_m;
  report.has_flat_start = true;
  report.flat_start = {flat.frames, flat.largest_seam_gap_m, flat.closed_below_m,
                       flat.wall_seconds};
  if (problem_.body) friction_.place(*problem_.body, x_);
}

void MassSpringBackend::prepare_step(const LoadStep& step) {
  friction_committed_ = false;
  if (problem_.body && friction_.active() && !friction_.placed())
    friction_.place(*problem_.body, x_);
  // The body may have changed since the last step (a morph, a growth): nothing of its last
  // queries is known to hold.
  std::fill(clearance_m_.begin(), clearance_m_.end(), 0.0);
  if (parameters_.integrator == Integrator::implicit) predict(step.alpha);
  time_step_s_ = choose_time_step_s();
  damping_per_s_ = parameters_.damping_per_s > 0
                       ? parameters_.damping_per_s
                       : critical_damping_per_s(problem_.law->stiffness_scale(),
                                                problem_.fabric->areal_density_kg_per_m2, size_m_);
  run_->step = step;
  run_->start_x = x_;
  run_->runaway_m = 10.0 * size_m_;
  std::fill(v_.begin(), v_.end(), Vec3::Zero());
}

MultiplierRound MassSpringBackend::settle(const LoadStep& step) {
  const int first_frame = run_->frame;
  MultiplierRound round =
      parameters_.integrator == Integrator::implicit ? settle_implicit(step) : settle_rk4(step);
  round.iterations = run_->frame - first_frame;
  return round;
}

// The implicit route: Newton from the current state to the same stop rule; `frame` counts its
// factorisations.
MultiplierRound MassSpringBackend::settle_implicit(const LoadStep& step) {
  StepRun& run = *run_;
  const bool assisted = rk4_assists_newton();
  if (assisted && !run.approached) {
    // The approach by RK4 frames (massspring_parameters.h): the garment's travel onto the body,
    // where the contact set changes from one iteration to the next, is Newton's slow part.
    run.approached = true;
    approaching_ = true;
    settle_rk4(step);
    approaching_ = false;
  }
  StaticNewton::Hooks hooks = newton_hooks();
  if (assisted) hooks.stall_iterations = 10;
  // Newton's stop is one number for the whole solve (static_newton.h): each state's residual is
  // read on the tension-scale rule's scale, r x tolerance / (its state's threshold), against the
  // tension-scale rule (or a round's inexact stop at the state it starts from).
  residual_forces(x_, step.gravity_on, force_);
  const double newton_stop_N = settle_stop_N() * tolerance_N_ / stop_threshold_N_;
  const StaticNewton::Result r = newton_.solve(
      x_, mass_kg_,
      [&](const std::vector<Vec3>& x, std::vector<Vec3>& force) {
        return residual_forces(x, step.gravity_on, force) * tolerance_N_ / stop_threshold_N_;
      },
      [&](const std::vector<Vec3>& x, SparseMatrix& K) { stiffness(x, K); }, newton_stop_N,
      1.0 / damping_per_s_, parameters_.maximum_newton_iterations - run.newton_iterations, hooks);
  run.frame += r.iterations;
  run.newton_iterations += r.iterations;
  run.residual_N = r.residual_N * stop_threshold_N_ / tolerance_N_;
  run.newton_history += (run.newton_history.empty() ? "" : "; ") + r.history;
  if (r.stalled) {
    // Newton stalled (on a mesh body's smooth surface, where the contact force jumps under
    // displacements of nanometres): RK4 frames finish the settle from where it stopped.
    std::fill(v_.begin(), v_.end(), Vec3::Zero());
    ++run.newton_stalls;
    return settle_rk4(step);
  }
  if (!r.converged) {
    std::ostringstream what;
    what << "did not reach equilibrium (implicit integrator, " << run.newton_iterations
         << " Newton iterations, Mass spring/Maximum Newton iterations "
         << parameters_.maximum_newton_iterations << "); " << run.newton_history;
    throw step_failure(
        std::isfinite(r.residual_N) ? StopReason::iteration_limit : StopReason::not_finite,
        what.str(), std::isfinite(r.residual_N));
  }
  MultiplierRound round;
  round.residual_N = {r.residual_N};
  return round;
}

// Damped RK4 from the current state until the stop rule holds. A stalled window halves the
// time step (residual_history.h) until the halvings run out.
MultiplierRound MassSpringBackend::settle_rk4(const LoadStep& step) {
  StepRun& run = *run_;
  int& frame = run.frame;
  run.history.restart();
  // A later contact round starts near the last round's equilibrium with its multipliers changed:
  // the time step halved for the last round's stall returns to its stable size. The damped
  // motion decays by the same factor per unit of simulated time at either step, so a kept
  // halving only multiplies the round's frames; a stall of this round halves it again. (A step's
  // first settle starts with none.)
  if (run.halvings > 0) {
    run.halvings = 0;
    time_step_s_ = choose_time_step_s();
  }
  MultiplierRound round;
  for (;;) {
    // The paper's quasi-static start (Section 4.3): velocity ignored, reset every frame.
    const bool quasi_static = frame < parameters_.quasi_static_frames;
    if (quasi_static) std::fill(v_.begin(), v_.end(), Vec3::Zero());
    const double c = quasi_static ? 0.0 : run.sliding ? run.slide_per_s : damping_per_s_;
    // While the garment slides the stop rule is not read: at the slide's lower damping a
    // creep shows a smaller net force (massspring_parameters.h).
    // The stop rule, or a round's inexact one, at the frame's start (settle_stop_N).
    run.residual_N = rk4_frame(time_step_s_, c, step.gravity_on, !run.sliding);
    if (!std::isfinite(run.residual_N))
      throw step_failure(StopReason::not_finite,
                         "diverged (non-finite force; try a smaller Mass spring/Time step)", false);
    if (run.sliding) {
      if (!quasi_static && slide_has_ended(time_step_s_, run.slide_per_s, run.calm_s)) {
        run.sliding = false;
        run.slide_frames = frame + 1 - run.slide_start_frame;
        run.history.restart();
      }
    } else if (run.residual_N < frame_stop_N_) {
      break;  // rk4_frame left the stable state untouched
    } else if (run.history.record(frame, run.residual_N, time_step_s_)) {
      if (run.may_creep_slide && creeping(c)) {
        // Stalled in a creep (massspring_parameters.h, creep_slide_damping_per_s): the rest of
        // it slides at the lower damping, and the time step keeps its size.
        run.may_creep_slide = false;
        run.sliding = true;
        run.slide_per_s = parameters_.creep_slide_damping_per_s;
        run.slide_start_frame = frame;
        run.calm_s = 0.0;
      } else {
        if (run.halvings == parameters_.stall_halvings)
          throw step_failure(StopReason::stalled,
                             "stalled (the residual did not fall below Mass spring/Stall "
                             "residual fall times its earlier windows' after " +
                                 std::to_string(run.halvings) + " time step halvings)",
                             true);
        time_step_s_ *= 0.5;
        ++run.halvings;
        ++run.step_halvings;
        run.history.restart();
      }
    }
    ++frame;
    if (parameters_.time_step_update_frames > 0 && parameters_.time_step_s == 0 &&
        frame % parameters_.time_step_update_frames == 0)
      time_step_s_ = std::ldexp(choose_time_step_s(), -run.halvings);
    throw_if_interrupted(interruption_signal(),
                         "during " + step_name(step) + " at frame " + std::to_string(frame));
    if (frame % 64 == 0)
      for (std::size_t i = 0; i < x_.size(); ++i)
        if (!((x_[i] - run.start_x[i]).norm() < run.runaway_m))
          throw step_failure(StopReason::ran_away,
                             "diverged (vertex " + std::to_string(i) + " ran away)", false);
    if (frame >= parameters_.maximum_frames) {
      run.residual_N = residual_forces(x_, step.gravity_on, force_);
      if (!run.sliding && run.residual_N < stop_threshold_N_) break;
      throw step_failure(run.sliding ? StopReason::still_sliding : StopReason::iteration_limit,
                         run.sliding
                             ? "was still sliding (Mass spring/Slide damping) at Mass "
                               "spring/Maximum frames"
                             : "did not reach equilibrium within Mass spring/Maximum frames",
                         true);
    }
  }
  round.residual_N = {run.residual_N};
  return round;
}

void MassSpringBackend::finish_report(const LoadStep& step, StepReport& report) {
  const StepRun& run = *run_;
  const bool implicit = parameters_.integrator == Integrator::implicit;
  // The residual at the end, in newtons, and the threshold it met at the end's contact load (the
  // net force's limit tightened with it, residual_forces). The net force as the stop rule saw it:
  // friction from the anchors the step solved with (committing them moves them onto the state
  // and takes their force away).
  write_step_header("mass spring", step, tolerance_N_, parameters_.stop.norm, report);
  report.residual_N = residual_forces(x_, step.gravity_on, force_);
  report.net_force_N = net_force_N(force_);
  report.net_force_read = true;
  report.load_tolerance_N = stop_threshold_N_;
  report.net_force_limit_N = net_force_limit_at_N(stop_threshold_N_);
  const int slipping = commit_friction_anchors();
  // How many vertices the committed friction anchors let slide (Coulomb cone reached).
  report.n_slipping = friction_.active() ? slipping : -1;
  report.stop_reason = StopReason::converged;
  report.iterations = report.flat_start.frames + run.frame;
  if (implicit) {
    report.has_newton = true;
    report.newton.first_pseudo_time_step_s = 1.0 / damping_per_s_;
  } else {
    report.has_relaxation = true;
    RelaxationReport& r = report.relaxation;
    r.quasi_static_frames = std::min(run.frame, parameters_.quasi_static_frames);
    r.slide_damping_per_s = run.slide_per_s;
    r.slide_frames = run.slide_frames;
    r.time_step_halvings = run.step_halvings;
    r.time_step_s = time_step_s_;
    r.damping_per_s = damping_per_s_;
    if (run.step_halvings > 0) r.stall_history = run.history.text();
  }
  run.clock.read(report);
}

StepReport MassSpringBackend::solve(const LoadStep& step) {
  run_ = std::make_unique<StepRun>(parameters_);
  StepReport report;
  run_flat_start(step, report);
  prepare_step(step);
  // Uzawa's iteration on the contact multipliers (core/load_step.h); the multipliers carry
  // over to the next load step as its start.
  MultiplierRounds rounds;
  rounds.settle = [&] { return settle(step); };
  rounds.max_updates = parameters_.contact_updates;
  rounds.gap_tolerance_m = parameters_.stop.gap_tolerance_m;
  // Inexact rounds: only a settle an update follows may stop early. The rounds settle once more
  // without an update after an update that finds the gap closed (core/load_step.h), and that
  // settle, or the plain penalty's only one, meets the stop rule.
  // On a body whose queries are costly only (a mesh body, where a frame costs most): the
  // analytic bodies' rounds, cheap already, keep their states to the last digit. Not with
  // friction or the rms stop rule: a dressed top's rms residual, far below its largest, stopped
  // its rounds within frames, and their updates no longer closed the gap in the 10 allowed.
  bool inexact = rounds.max_updates > 0 && rounds.settle_after_last_update && carry_contact_ &&
                 parameters_.stop.norm == StopNorm::largest &&
                 parameters_.inexact_round_fraction > 0 &&
                 (parameters_.integrator == Integrator::rk4 || rk4_assists_newton());
  final_settle_next_ = !inexact;
  // An inexact round whose update leaves more than a quarter of the last update's penetration
  // settles exactly from then on: a slow mode still moving under the early stops (the stocking at
  // half resolution, 16 mm x 30 mm, sliding round the ankle) keeps reopening the gaps each update
  // closes, where the exact rounds close them 25-fold per update (docs/stocking.md).
  constexpr double inexact_gap_fall = 0.25;
  double last_update_penetration_m = std::numeric_limits<double>::infinity();
  rounds.read_gap = [&](bool update, int* count) {
    const double penetration_m = contact_penetration_m(update, count);
    if (inexact && update) {
      if (penetration_m > inexact_gap_fall * last_update_penetration_m) inexact = false;
      last_update_penetration_m = penetration_m;
    }
    final_settle_next_ = !inexact || (update && penetration_m <= rounds.gap_tolerance_m);
    return penetration_m;
  };
  if (!rounds.run(report)) {
    const std::string what =
        gap_not_closed_text(report, parameters_.stop.gap_tolerance_m) +
        " (their settles stop once below Mass spring/Inexact contact rounds times the next "
        "update's largest change)";
    // Where the residual sits: a garment still moving over the body (a creep round a limb)
    // keeps changing the gaps each update closes.
    throw step_failure(StopReason::gap_not_closed, what, true);
  }
  if (parameters_.integrator == Integrator::implicit)
    record_settled(step.alpha, report.n_in_contact > 0);
  finish_report(step, report);
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
