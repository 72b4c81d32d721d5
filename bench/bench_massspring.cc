// Time for the mass-spring backend to reach a stable state of the paper's cylinder study
// (Sections 4.3 and 7.4): the "4 5T" tube on a rigid cylinder, linear Biot with zero Poisson
// ratio, free ends, no gravity, penalty factor 50. The paper's simulator needed more than 5000
// frames, about 10 minutes per state, on a 3 GHz Pentium IV.
//
// Each iteration places the sewn tube at the radius of the previous state and solves one load
// step to the new radius, so it times exactly one stable state as a load-stepping run meets it.
#include "contact/cylinder.h"
#include "contact/penalty_contact.h"
#include "core/tube_garment.h"
#include "massspring/lumped_mass.h"
#include "massspring/massspring_backend.h"
#include "massspring/sewn_tube_placement.h"

#include <benchmark/benchmark.h>

#include <cmath>

namespace {

using namespace tightfit;

constexpr double panel_width_m = 0.1878, height_m = 0.24;

// Solves to alpha_from, then (timed) from there to alpha_to. `spacing_scale` shrinks the default
// mesh spacing (0.63 gives the paper's finer 1397-vertex mesh).
void stable_state(benchmark::State& bench, double alpha_from, double alpha_to,
                  double spacing_scale) {
  MeshSpacing spacing;
  spacing.along_x_m *= spacing_scale;
  spacing.along_y_m *= spacing_scale;
  const SimulationMesh mesh = weld(make_tube_garment("4 5T", panel_width_m, height_m, 2, spacing));
  FabricParameters fabric;
  fabric.poisson_weft_warp = 0.0;
  const auto law = make_material_law("linear biot", fabric);
  const double circumference_m = 2 * panel_width_m;
  const double R0 = circumference_m / (2 * M_PI);
  Cylinder cylinder(Vec3::Zero(), Vec3::UnitZ(), alpha_from * R0);
  Problem problem;
  problem.mesh = &mesh;
  problem.law = law.get();
  problem.fabric = &fabric;
  problem.body = &cylinder;
  problem.contact_stiffness_Pa_per_m =
      penalty_stiffness_Pa_per_m(50.0, law->stiffness_scale(), mean_rest_edge_length_m(mesh));

  MassSpringBackend backend(problem, MassSpringParameters{});
  backend.set_positions(
      sewn_tube_positions(mesh, circumference_m, height_m, std::max(1.0, alpha_from) * R0));
  backend.solve(LoadStep{0, alpha_from, false});
  const std::vector<Vec3> start = backend.state().positions_m;

  StepReport report;
  for (auto _ : bench) {
    bench.PauseTiming();
    cylinder.set_radius(alpha_from * R0);
    backend.set_positions(start);
    cylinder.set_radius(alpha_to * R0);
    bench.ResumeTiming();
    report = backend.solve(LoadStep{1, alpha_to, false});
    benchmark::DoNotOptimize(report);
  }
  bench.counters["vertices"] = mesh.n_vertices;
  bench.counters["frames"] = report.iterations;
  bench.counters["us_per_frame"] =
      report.iterations > 0 ? 1e6 * report.wall_seconds / report.iterations : 0.0;
}

void settle_at_alpha_1_2(benchmark::State& s) {
  stable_state(s, 1.2, 1.2, 1.0);
}
void step_1_2_to_1_5(benchmark::State& s) {
  stable_state(s, 1.2, 1.5, 1.0);
}
void step_1_5_to_1_8(benchmark::State& s) {
  stable_state(s, 1.5, 1.8, 1.0);
}
// The cases' load stepping: ten steps from the 5 cm cylinder to alpha 1.8 (one of them).
void step_1_72_to_1_8(benchmark::State& s) {
  stable_state(s, 1.72, 1.8, 1.0);
}
void fine_step_1_2_to_1_5(benchmark::State& s) {
  stable_state(s, 1.2, 1.5, 0.63);
}
void fine_step_1_5_to_1_8(benchmark::State& s) {
  stable_state(s, 1.5, 1.8, 0.63);
}

BENCHMARK(settle_at_alpha_1_2)->Unit(benchmark::kMillisecond);
BENCHMARK(step_1_2_to_1_5)->Unit(benchmark::kMillisecond);
BENCHMARK(step_1_5_to_1_8)->Unit(benchmark::kMillisecond);
BENCHMARK(step_1_72_to_1_8)->Unit(benchmark::kMillisecond);
BENCHMARK(fine_step_1_2_to_1_5)->Unit(benchmark::kMillisecond);
BENCHMARK(fine_step_1_5_to_1_8)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
