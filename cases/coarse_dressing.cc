#include "cases/coarse_dressing.h"

#include "bodies/surface_return.h"
#include "cases/scenario.h"
#include "core/backend_registry.h"
#include "core/mesh_transfer.h"

#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace tightfit {

std::vector<Vec3> dressed_from_coarse(const Scenario& scenario, double coarse_m,
                                      const CoarseSettle& settle_rule,
                                      const PlacementMaker& dress_coarse,
                                      const std::string& section) {
  if (scenario.parameters.garment.kind != "pattern file")
    throw std::invalid_argument(
        section +
        "/Coarse edge length: only a garment cut from a pattern "
        "(Garment/Kind = pattern file) is meshed at another edge length, not Garment/Kind = " +
        scenario.parameters.garment.kind);
  if (settle_rule.slide_damping_per_s > 0 && !(settle_rule.net_force_tolerance > 0) &&
      !scenario.parameters.stop_rule.rough_mesh_body)
    throw std::invalid_argument(
        section +
        "/Coarse slide damping needs a Coarse net force tolerance above 0 on this body (the end "
        "of the slide is read on the net force limit; on a body mesh touched on its flat faces or "
        "by a garment held by friction the settle has one by default)");
  CaseParameters coarse = scenario.parameters;
  coarse.garment.spacing.pattern_edge_length_m = coarse_m;
  coarse.placement.place = dress_coarse;
  std::unique_ptr<Scenario> dressed;
  try {
    dressed = make_scenario(coarse);
  } catch (const SolverError& error) {
    std::ostringstream message;
    message << "on the coarse mesh (" << section << "/Coarse edge length " << coarse_m
            << " m): " << error.what();
    throw SolverError(error.reason(), message.str(), error.failure());
  }
  std::vector<Vec3> coarse_x = dressed->start_positions_m;
  if (settle_rule.relative_tolerance > 0) {
    CoarseSettle rule = settle_rule;
    rule.rough_mesh_body = scenario.parameters.stop_rule.rough_mesh_body;
    const SettledGarment settled = backend_registry().dressing_stage().settle(
        dressed->problem, coarse_x, dressed->prepare_step(0), rule);
    std::printf("  dressing: the coarse mesh settled: %s\n", settled.report.text().c_str());
    coarse_x = settled.positions_m;
  }
  std::vector<Vec3> x = transfer_positions(dressed->mesh, coarse_x, scenario.mesh);
  const double allowed_m = 0.25 * dressed->mean_edge_length_m;
  const SurfaceReturn back = return_onto_surface(*scenario.problem.body, x, allowed_m);
  if (back.deepest_m > allowed_m) {
    std::ostringstream message;
    message << "dressing: carried from the coarse mesh, vertex " << back.deepest_point << " lies "
            << back.deepest_m << " m inside the body (more than a quarter of a coarse edge, "
            << allowed_m << " m); dress on a finer coarse mesh (" << section
            << "/Coarse edge length)";
    throw SolverError(StopReason::passed_into_body, message.str());
  }
  std::printf(
      "  dressing: carried from the coarse mesh (%d vertices, mean edge %.3g m) to %d vertices; "
      "%d put back on the body from at most %.3g m inside\n",
      dressed->mesh.n_vertices, dressed->mean_edge_length_m, scenario.mesh.n_vertices,
      back.points_moved, back.deepest_m);
  std::fflush(stdout);
  return x;
}

void print_dressing(const DressingResult& dressed) {
  if (dressed.vertices_pushed_out > 0)
    std::printf(
        "  dressing: %d start vertices inside the shrunk body pushed out along its normal, the "
        "deepest from %.3g m\n",
        dressed.vertices_pushed_out, dressed.deepest_push_m);
  std::printf(
      "  dressing: seams closed (largest gap %.3g m < %.3g m) after %d frames, %.1f s; %d "
      "welded vertices put back on the body from at most %.3g m inside\n",
      dressed.largest_seam_gap_m, dressed.closed_below_m, dressed.frames, dressed.wall_seconds,
      dressed.vertices_put_back, dressed.deepest_m);
  std::fflush(stdout);
}

}  // namespace tightfit
