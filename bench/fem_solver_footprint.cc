// Memory and time of the FE backend's linear solvers on one load step of the 4 5T tube, with
// no loose start: the tube is placed round the cylinder at alpha R0 and solved there, so that
// an iterative solver never falls back to MUMPS (the loose tube's singular tangent defeats it,
// docs/performance.md) and the resident set is the solver's own. Runs under mpirun too.
//
// Usage: [mpirun -np N] fem_solver_footprint SCALE SOLVER [ALPHA [MEMORY]]
//   SCALE: the mesh spacing as a fraction of the paper's coarse mesh (0.8 cm round, 2.2 cm
//   along; 0.073 gives about 97000 vertices); SOLVER: a `Finite elements/Linear solver` name;
//   ALPHA: the cylinder's radius over the tube's (default 1.1); MEMORY: a `Finite
//   elements/Iterative solver memory` name (default fast).
// The garment and its mesh are built on rank 0 only (the FE backend sends each rank its part).
// Prints, per rank, the resident set with MPI and PETSc started (the libraries' floor, which no
// distribution lowers), after the garment's mesh is built (rank 0's), after the backend's
// setup, the peak
// up to then (the setup's, with the deal.II triangulation it frees) and the peak over the run
// (MB), the resident set after the step (the solver's state it keeps and the step's output),
// and the step's Newton and Krylov iterations, wall and CPU time.
#include "../tests/fem/tube_problem.h"
#include "fem/fem_backend.h"

#include <deal.II/base/mpi.h>

#include <mpi.h>
#include <sys/resource.h>

#include <cstdio>
#include <ctime>
#include <fstream>
#include <string>

namespace {

// This process's resident set now (VmRSS), MB.
double resident_MB() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    double kB = 0.0;
    if (key == "VmRSS:" && status >> kB) return kB / 1024.0;
    status.ignore(1 << 20, '\n');
  }
  return 0.0;
}

double peak_resident_MB() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace tightfit;
  if (argc < 3 || argc > 5) {
    std::fprintf(stderr, "usage: fem_solver_footprint SCALE SOLVER [ALPHA [MEMORY]]\n");
    return 2;
  }
  // MPI and PETSc first, so that the floor is measured before any garment data exists.
  dealii::Utilities::MPI::MPI_InitFinalize runtime(argc, argv, 1);
  const double floor_MB = resident_MB();
  const double scale = std::stod(argv[1]);
  const double alpha = argc >= 4 ? std::stod(argv[3]) : 1.1;
  FemParameters parameters;
  bool known = false;
  for (const LinearSolverKind kind :
       {LinearSolverKind::direct, LinearSolverKind::cg_amg, LinearSolverKind::gmres_amg,
        LinearSolverKind::cg_gamg, LinearSolverKind::gmres_gamg})
    if (argv[2] == std::string(to_string(kind))) {
      parameters.linear_solver = kind;
      known = true;
    }
  const std::string memory = argc == 5 ? argv[4] : "fast";
  if (memory == to_string(IterativeSolverMemory::lean))
    parameters.iterative_solver_memory = IterativeSolverMemory::lean;
  else if (memory != to_string(IterativeSolverMemory::fast))
    known = false;
  if (!known || !(scale > 0.0) || !(alpha > 1.0)) {
    std::fprintf(stderr, "fem_solver_footprint: bad solver '%s', scale, alpha or memory\n",
                 argv[2]);
    return 2;
  }
  testing::TubeCase tube("st venant kirchhoff", EndCondition::free_ends,
                         MeshSpacing{scale * 0.008, scale * 0.022}, testing::MeshOnFirstRank{});
  const double mesh_MB = resident_MB();
  FemBackend backend(tube.problem, parameters);
  int rank = 0, n_ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &n_ranks);
  tube.grow_to(alpha);
  backend.set_positions(tube.placed(alpha * tube.rest_radius_m));
  const double setup_MB = resident_MB();
  const double setup_peak_MB = peak_resident_MB();
  const std::clock_t cpu_start = std::clock();
  const StepReport report = backend.solve({0, alpha, false});
  const double cpu_s = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  const double step_MB = resident_MB();        // the solver's state kept, and the step's output
  const SurfaceState state = backend.state();  // collective
  double mean_Pa = rank == 0 ? tube.pressure(state).mean_Pa : 0.0;
  MPI_Bcast(&mean_Pa, 1, MPI_DOUBLE, 0, MPI_COMM_WORLD);
  for (int r = 0; r < n_ranks; ++r) {
    MPI_Barrier(MPI_COMM_WORLD);
    if (r == rank)
      std::printf(
          "rank %d of %d: %d vertices, %s: resident %.0f MB with MPI and PETSc started, "
          "%.0f MB with the mesh, %.0f MB after setup, peak %.0f MB (%.0f MB above the "
          "first); %.1f s CPU, p_mean %.10f Pa; setup peak %.0f MB; %.0f MB after the step; "
          "memory %s\n",
          rank, n_ranks, tube.n_vertices(), argv[2], floor_MB, mesh_MB, setup_MB,
          peak_resident_MB(), peak_resident_MB() - floor_MB, cpu_s, mean_Pa, setup_peak_MB, step_MB,
          memory.c_str());
    std::fflush(stdout);
  }
  if (rank == 0) std::printf("%s\n", report.text().c_str());
  return 0;
}
