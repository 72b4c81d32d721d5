// Mass spring/Time step update frames: the automatic time step chosen again during a load step
// follows the state. A tube started with one edge squashed to 0.3 of its length (as a state
// carried from a coarse mesh may be) starts at a smaller step; with the updates it ends at the
// step of the settled state, and settles to the same state.
#include "massspring/massspring_backend.h"
#include "test_meshes.h"
#include "tube_on_cylinder.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

namespace tightfit {
namespace {

struct Settled {
  SurfaceState state;
  double time_step_s;
  int frames;
};

Settled settle(const test::TubeOnCylinder& tube, const std::vector<Vec3>& start,
               int update_frames) {
  MassSpringParameters parameters;
  parameters.contact_updates = 0;
  parameters.time_step_update_frames = update_frames;
  MassSpringBackend backend(tube.problem, parameters);
  backend.set_positions(start);
  const StepReport report = backend.solve(LoadStep{0, 1.3, false});
  return {backend.state(), backend.time_step_s(), report.iterations};
}

double total_contact_force_N(const SurfaceState& s) {
  double total = 0.0;
  for (const Vec3& f : s.contact_force_N) total += f.norm();
  return total;
}

TEST(MassSpringSolver, TimeStepUpdatesFollowTheStateFromASquashedStart) {
  test::TubeOnCylinder tube(0.157, MeshSpacing{});
  tube.cylinder.set_radius(1.3 * tube.rest_radius_m());
  std::vector<Vec3> start = tube.start_positions();
  const Triangle& t = tube.mesh.triangles[0];
  start[t[0]] = start[t[1]] + 0.3 * (start[t[0]] - start[t[1]]);

  const Settled once = settle(tube, start, 0);
  const Settled updated = settle(tube, start, 10);
  // The step the settled state itself asks for: a step started there, chosen once.
  const Settled from_rest = settle(tube, updated.state.positions_m, 0);
  std::printf(
      "time step: squashed start %.6g s, with updates at the end %.6g s, at the settled "
      "state %.6g s; frames %d and %d\n",
      once.time_step_s, updated.time_step_s, from_rest.time_step_s, once.frames, updated.frames);
  EXPECT_LT(once.time_step_s, 0.8 * from_rest.time_step_s);
  // Chosen at most 10 frames before the stop, within the stop rule of the settled state.
  EXPECT_NEAR(updated.time_step_s / from_rest.time_step_s, 1.0, 1e-3);
  EXPECT_LT(updated.frames, once.frames);
  // The same equilibrium: within the stop rule (1e-4 of a vertex's contact force, as in
  // ContactMultipliersRemoveThePenaltyFromThePressure).
  EXPECT_NEAR(total_contact_force_N(updated.state) / total_contact_force_N(once.state), 1.0,
              1.4e-4);
}

}  // namespace
}  // namespace tightfit
