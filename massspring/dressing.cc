#include "massspring/dressing.h"

#include "bodies/surface_return.h"

#include "bodies/rigid_body.h"
#include "bodies/scaled_body.h"
#include "bodies/skeleton_shrunk_body.h"
#include "core/interruption.h"
#include "massspring/massspring_parameters.h"
#include "massspring/open_seam_garment.h"
#include "massspring/unwelded_panels.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace tightfit {

namespace {

// The backend's settings for the dressing's motion: its defaults (time step, quasi-static
// frames, bending rigidity) and the stage's seam stiffness and damping.
MassSpringParameters dressing_parameters(const DressingSettings& settings) {
  MassSpringParameters parameters;
  parameters.seam_stiffness_factor = settings.seam_stiffness_factor;
  parameters.damping_per_s = settings.damping_per_s;
  return parameters;
}

// The panel an unwelded vertex belongs to, and its index in that panel.
std::pair<int, int> panel_vertex(const SimulationMesh& mesh, int u) {
  const auto& offsets = mesh.panel_vertex_offset;
  const int p = int(std::upper_bound(offsets.begin(), offsets.end(), u) - offsets.begin()) - 1;
  return {p, u - offsets[p]};
}

bool lists(const std::vector<int>& edge, int vertex) {
  return std::find(edge.begin(), edge.end(), vertex) != edge.end();
}

std::string where(const Vec3& x) {
  std::ostringstream out;
  out << "(" << x.x() << ", " << x.y() << ", " << x.z() << ") m";
  return out.str();
}

double ramp(int frame, int frames) {
  return frames <= 0 ? 1.0 : std::min(1.0, double(frame) / frames);
}

// The body shrunk as the settings say: about its skeleton, an axis or a point.
std::unique_ptr<ShrinkingBody> shrinking_body(const RigidBody& whole,
                                              const DressingSettings& settings) {
  if (!settings.skeleton.empty()) {
    const DisplayMesh mesh = whole.display_mesh();
    TriangleSurface surface;
    surface.vertices_m = mesh.vertices_m;
    surface.triangles = mesh.triangles;
    Vec3 up = Vec3::UnitZ();
    for (const SkeletonBone& bone : settings.skeleton)
      if (bone.name == "torso") up = (bone.end_m - bone.root_m).normalized();
    const double per_unit = settings.start_scale < 1.0
                                ? settings.skeleton_arm_raise_rad / (1.0 - settings.start_scale)
                                : 0.0;
    return std::make_unique<SkeletonShrunkBody>(std::move(surface), settings.skeleton,
                                                settings.skeleton_blend_m, 0.005, per_unit, up,
                                                settings.skeleton_shortens_torso);
  }
  if (settings.scale_axis)
    return std::make_unique<ScaledBody>(whole, settings.centre_m, *settings.scale_axis);
  return std::make_unique<ScaledBody>(whole, settings.centre_m);
}

DressingSnapshot snapshot(const OpenSeamGarment& open, const ShrinkingBody& body, int frame) {
  DressingSnapshot s;
  s.frame = frame;
  s.body_scale = body.scale();
  s.positions_m = open.positions();
  s.triangles = open.panels().mesh.triangles;
  s.seam_gap_m.assign(s.positions_m.size(), 0.0);
  s.seam_partner.assign(s.positions_m.size(), -1);
  for (const auto& [a, b] : open.panels().seam_pairs) {
    const double gap = (s.positions_m[a] - s.positions_m[b]).norm();
    for (const auto& [u, w] : {std::pair<int, int>{a, b}, {b, a}})
      if (s.seam_partner[u] < 0 || gap > s.seam_gap_m[u]) {
        s.seam_gap_m[u] = gap;
        s.seam_partner[u] = w;
      }
  }
  s.body_distance_m.reserve(s.positions_m.size());
  for (const Vec3& x : s.positions_m) s.body_distance_m.push_back(body.query(x).signed_distance_m);
  s.body = body.display_mesh();
  return s;
}

}  // namespace

std::string seam_joining(const Garment& garment, const SimulationMesh& mesh, int a, int b) {
  const auto [pa, va] = panel_vertex(mesh, a);
  const auto [pb, vb] = panel_vertex(mesh, b);
  for (const Seam& seam : garment.seams) {
    const auto& edges_a = garment.panels[seam.panel_a].edges;
    const auto& edges_b = garment.panels[seam.panel_b].edges;
    const auto on = [](const std::map<std::string, std::vector<int>>& edges,
                       const std::string& name, int v) {
      const auto found = edges.find(name);
      return found != edges.end() && lists(found->second, v);
    };
    const bool forward = seam.panel_a == pa && seam.panel_b == pb && on(edges_a, seam.edge_a, va) &&
                         on(edges_b, seam.edge_b, vb);
    const bool backward = seam.panel_a == pb && seam.panel_b == pa &&
                          on(edges_a, seam.edge_a, vb) && on(edges_b, seam.edge_b, va);
    if (forward || backward)
      return garment.panels[seam.panel_a].name + ":" + seam.edge_a + " -- " +
             garment.panels[seam.panel_b].name + ":" + seam.edge_b;
  }
  return "the seam joining " + garment.panels[pa].name + " vertex " + std::to_string(va) + " and " +
         garment.panels[pb].name + " vertex " + std::to_string(vb);
}

DressingResult dress(const Problem& problem, const Garment& garment,
                     const std::vector<Vec3>& start_m, const DressingSettings& settings) {
  const auto clock_start = std::chrono::steady_clock::now();
  if (!problem.body) throw std::invalid_argument("dressing: the problem has no body");
  if (!(settings.start_scale > 0.0 && settings.start_scale <= 1.0))
    throw std::invalid_argument("dressing: the body's start scale must lie in (0, 1]");
  const SimulationMesh& welded = *problem.mesh;
  OpenSeamGarment open(problem, dressing_parameters(settings));
  if (static_cast<int>(start_m.size()) != welded.n_unwelded_vertices())
    throw std::invalid_argument("dressing: " + std::to_string(start_m.size()) +
                                " start positions for " +
                                std::to_string(welded.n_unwelded_vertices()) + " panel vertices");
  const std::unique_ptr<ShrinkingBody> shrinking = shrinking_body(*problem.body, settings);
  ShrinkingBody& body = *shrinking;
  body.set_scale(settings.start_scale);
  open.set_body(&body);

  std::vector<Vec3>& x = open.positions();
  std::vector<Vec3>& v = open.velocities();
  x = start_m;
  std::fill(v.begin(), v.end(), Vec3::Zero());
  // A start vertex inside the shrunk body goes out along the body's normal by the depth found
  // (and a clearance of a tenth of a mean edge), so that a placement that touches the body
  // still dresses; deeper than half the garment's size it is no near miss but a placement on
  // the wrong side of the body, refused.
  DressingResult result;
  const double push_limit_m = 0.5 * open.size_m();
  const double push_clearance_m = 0.1 * open.mean_edge_m();
  for (std::size_t u = 0; u < x.size(); ++u) {
    const SurfacePoint found = body.query(x[u]);
    const double g = found.signed_distance_m;
    if (g >= 0.0) continue;
    if (-g > push_limit_m) {
      const auto [p, i] = panel_vertex(welded, int(u));
      std::ostringstream message;
      message << "dressing: panel " << garment.panels[p].name << " vertex " << i << " starts " << -g
              << " m inside the body shrunk to " << settings.start_scale << " at " << where(x[u])
              << " (more than half the garment's size, " << push_limit_m
              << " m); place the panels further out or shrink the body more";
      throw std::invalid_argument(message.str());
    }
    x[u] += (push_clearance_m - g) * found.outward_normal;
    ++result.vertices_pushed_out;
    result.deepest_push_m = std::max(result.deepest_push_m, -g);
  }

  result.closed_below_m = settings.closed_fraction * open.mean_edge_m();
  // A zero-rest-length spring as stiff as the seam's closing needs pulls a seam vertex a far
  // gap away (tenths of a metre round a body) hundreds of times harder than its panel's
  // membrane holds it: the vertex leaves its panel and swings past its partner. Beyond the
  // closing gap the pull stays at the closing gap's (docs/cookbook-jumpsuit.md).
  if (settings.limit_seam_pull)
    open.set_seam_pull_limit(open.full_seam_stiffness_N_per_m() * result.closed_below_m,
                             settings.sewn_stiffness_factor);
  if (settings.stiffness_over_mass_ratio > 0)
    open.limit_stiffness_over_mass(settings.stiffness_over_mass_ratio);
  const double runaway_m = 10.0 * open.size_m();
  const double damping = open.damping_per_s();
  double dt = 0.0;
  auto fail = [&](StopReason reason, const std::string& what) {
    const auto [a, b] = open.widest_seam_pair();
    std::ostringstream message;
    message << "dressing: " << what << " at frame " << result.frames << " (body scale "
            << body.scale() << "); the widest seam gap is " << result.largest_seam_gap_m
            << " m (closed below " << result.closed_below_m << " m)";
    if (a >= 0)
      message << ", on seam " << seam_joining(garment, welded, a, b) << " between " << where(x[a])
              << " and " << where(x[b]);
    if (settings.on_failure)
      message << "; " << settings.on_failure(snapshot(open, body, result.frames));
    return SolverError(reason, message.str());
  };

  // How far the body's surface can move as its scale changes by ds: ds times its reach.
  const double reach_m = body.reach_m();
  // The body grows a step after each frame that ends with every seam narrower than the growth
  // gap (when that is set; else after every frame), so that a seam still open far is not trapped
  // under a body part growing over it (a trouser leg's inseam between the thighs).
  const double growth_gap_m = settings.growth_gap_fraction * open.mean_edge_m();
  int growth_steps = 0;
  result.largest_seam_gap_m = open.largest_seam_gap_m();
  for (;;) {
    const double scale = settings.start_scale +
                         (1.0 - settings.start_scale) * ramp(growth_steps, settings.growth_frames);
    const double scale_before = body.scale();
    body.set_scale(scale);
    open.body_moved(std::abs(body.scale() - scale_before) * reach_m * 1.01);
    open.set_clearance_factor(scale);
    open.set_seam_fraction(ramp(result.frames + 1, settings.seam_ramp_frames));
    // The stiffness bounds move with the shape (a stiffening law's tangent); cheap at this rate.
    if (result.frames % 100 == 0) dt = open.time_step_s();
    const bool quasi_static = result.frames < open.parameters().quasi_static_frames;
    if (quasi_static) std::fill(v.begin(), v.end(), Vec3::Zero());
    open.rk4_frame(dt, quasi_static ? 0.0 : damping, false);
    ++result.frames;
    result.largest_seam_gap_m = open.largest_seam_gap_m();
    if (growth_gap_m <= 0.0 || result.largest_seam_gap_m < growth_gap_m) ++growth_steps;
    if (settings.limit_seam_pull) open.sew_closed_seams(result.closed_below_m);
    if (settings.progress && result.frames % settings.progress_frames == 0)
      *settings.progress
          << "  dressing: frame " << result.frames << ", body scale " << body.scale()
          << ", seam springs at " << ramp(result.frames, settings.seam_ramp_frames)
          << " of full, widest seam gap " << result.largest_seam_gap_m << " m, "
          << std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count()
          << " s" << std::endl;
    if (!std::isfinite(result.largest_seam_gap_m))
      throw fail(StopReason::not_finite,
                 "diverged (non-finite position; try a smaller Mass spring/Time step)");
    const bool whole =
        growth_steps >= settings.growth_frames && result.frames >= settings.seam_ramp_frames;
    if (whole && result.largest_seam_gap_m < result.closed_below_m) break;
    if (result.frames >= settings.maximum_frames)
      throw fail(
          StopReason::seams_not_closed,
          "the seams did not close within " + std::to_string(settings.maximum_frames) + " frames");
    throw_if_interrupted(interruption_signal(),
                         "during the dressing at frame " + std::to_string(result.frames));
    if (result.frames % 64 == 0)
      for (std::size_t u = 0; u < x.size(); ++u)
        if (!((x[u] - start_m[u]).norm() < runaway_m + push_limit_m))
          throw fail(StopReason::ran_away,
                     "diverged (panel vertex " + std::to_string(u) + " ran away)");
  }

  // Welded; every vertex must lie outside the whole body. The penalty leaves vertices in
  // contact p / k deep: those go back onto the surface along the distance's gradient.
  result.welded_positions_m = weld_positions(welded, x);
  const double allowed_m = settings.inside_fraction * open.mean_edge_m();
  const SurfaceReturn back =
      return_onto_surface(*problem.body, result.welded_positions_m, allowed_m);
  if (back.deepest_m > allowed_m) {
    std::ostringstream message;
    message << "dressing: welded vertex " << back.deepest_point << " ends " << back.deepest_m
            << " m inside the body at " << where(result.welded_positions_m[back.deepest_point])
            << " (more than " << allowed_m
            << " m: the garment passed into the body; grow it more slowly with more "
               "growth frames, or start it further out)";
    throw SolverError(StopReason::passed_into_body, message.str());
  }
  result.deepest_m = back.deepest_m;
  result.vertices_put_back = back.points_moved;
  result.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
  return result;
}

}  // namespace tightfit
