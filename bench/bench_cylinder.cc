// Speed of both backends on the paper's cylinder study (Sections 4.3 and 7.4): the "4 5T" tube
// on a rigid cylinder, linear Biot with zero Poisson ratio, free ends, no gravity. The paper's
// simulator needed more than 5000 frames, about 10 minutes per stable state, on a 3 GHz
// Pentium IV.
//
// - stable_state: the garment settled at alpha_from, then (timed) one load step to alpha_to:
//   one stable state as a load-stepping run meets it.
// - full_sweep: the whole protocol of cases/cylinder_45T.prm (settle on the 5 cm cylinder,
//   then alpha 0.85, 0.90, ..., 1.80), from the sewn start.
// Mesh scale 1 is the paper's coarse mesh (552 vertices), 0.62 its fine one (1444 vertices,
// 2736 triangles; the paper: 1397 and 2738).
#include "cases/case_parameters.h"
#include "cases/scenario.h"

#include <benchmark/benchmark.h>

#include <string>

namespace {

using namespace tightfit;

CaseParameters bench_parameters(const CaseFile& file, const std::string& backend,
                                double mesh_scale) {
  CaseParameters p = file.parameters();
  p.backend = backend;
  p.fabric.poisson_weft_warp = 0.0;
  p.garment.spacing.along_x_m *= mesh_scale;
  p.garment.spacing.along_y_m *= mesh_scale;
  return p;
}

void stable_state(benchmark::State& bench, const std::string& backend, double alpha_from,
                  double alpha_to, double mesh_scale) {
  const CaseFile file;
  CaseParameters p = bench_parameters(file, backend, mesh_scale);
  p.protocol.final_alpha = alpha_to;
  auto setup = make_scenario(p);
  setup->alphas = {alpha_from, alpha_to};
  auto solver = file.create_backend(backend, setup->problem);
  setup->prepare_step(0);
  setup->body->morph(1, alpha_from);  // the settled state at alpha_from
  solver->set_positions(setup->initial_positions());
  solver->solve(LoadStep{0, alpha_from, false});
  const std::vector<Vec3> settled = solver->state().positions_m;
  StepReport report;
  for (auto _ : bench) {
    bench.PauseTiming();
    solver->set_positions(settled);
    const LoadStep step = setup->prepare_step(1);
    bench.ResumeTiming();
    report = solver->solve(step);
    benchmark::DoNotOptimize(report);
  }
  bench.counters["vertices"] = setup->mesh.n_vertices;
  bench.counters["iterations"] = report.iterations;
}

void full_sweep(benchmark::State& bench, const std::string& backend, double mesh_scale) {
  const CaseFile file;
  const CaseParameters p = bench_parameters(file, backend, mesh_scale);
  int n_vertices = 0, n_steps = 0;
  for (auto _ : bench) {
    auto setup = make_scenario(p);
    auto solver = file.create_backend(backend, setup->problem);
    setup->prepare_step(0);
    solver->set_positions(setup->initial_positions());
    for (std::size_t k = 0; k < setup->alphas.size(); ++k)
      benchmark::DoNotOptimize(solver->solve(setup->prepare_step(static_cast<int>(k))));
    n_vertices = setup->mesh.n_vertices;
    n_steps = static_cast<int>(setup->alphas.size());
  }
  bench.counters["vertices"] = n_vertices;
  bench.counters["load_steps"] = n_steps;
}

}  // namespace

BENCHMARK_CAPTURE(stable_state, massspring_1_2_to_1_5, "massspring", 1.2, 1.5, 1.0)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(stable_state, massspring_1_75_to_1_8, "massspring", 1.75, 1.8, 1.0)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(stable_state, massspring_fine_1_75_to_1_8, "massspring", 1.75, 1.8, 0.62)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(stable_state, fem_1_75_to_1_8, "fem", 1.75, 1.8, 1.0)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(full_sweep, massspring_coarse, "massspring", 1.0)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);
BENCHMARK_CAPTURE(full_sweep, massspring_fine, "massspring", 0.62)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(2);
BENCHMARK_CAPTURE(full_sweep, fem_coarse, "fem", 1.0)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK_CAPTURE(full_sweep, fem_fine, "fem", 0.62)->Unit(benchmark::kMillisecond)->Iterations(2);

BENCHMARK_MAIN();
