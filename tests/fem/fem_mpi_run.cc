// The 2-rank check: `fem_mpi_run write FILE` solves the 4 5T tube on the
// cylinder (St. Venant-Kirchhoff, held ends, alpha 1.2 - 1.8) and writes the mean pressures;
// `mpirun -np 2 fem_mpi_run compare FILE` solves the same case with the mesh and the solves
// distributed and fails unless every mean pressure equals the serial one to 1e-8 relative.
// A third argument sets the element degree (1 by default), a fourth the linear solver by its
// parameter name (direct, MUMPS, by default; the reference is always written with it), a fifth
// `Finite elements/Iterative solver memory` (fast by default).
#include "fem/fem_backend.h"
#include "tube_problem.h"

#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  using namespace tightfit;
  if (argc < 3 || argc > 6) {
    std::fprintf(stderr,
                 "usage: fem_mpi_run write|compare FILE [ELEMENT_DEGREE [SOLVER [MEMORY]]]\n");
    return 2;
  }
  const std::string mode = argv[1], file = argv[2];
  const int degree = argc >= 4 ? std::stoi(argv[3]) : 1;
  LinearSolverKind solver = LinearSolverKind::direct;
  if (argc >= 5) {
    bool known = false;
    for (const LinearSolverKind kind :
         {LinearSolverKind::direct, LinearSolverKind::cg_amg, LinearSolverKind::gmres_amg,
          LinearSolverKind::cg_gamg, LinearSolverKind::gmres_gamg})
      if (argv[4] == std::string(to_string(kind))) {
        solver = kind;
        known = true;
      }
    if (!known) {
      std::fprintf(stderr, "fem_mpi_run: unknown linear solver '%s'\n", argv[4]);
      return 2;
    }
  }
  IterativeSolverMemory memory = IterativeSolverMemory::fast;
  if (argc == 6) {
    if (argv[5] == std::string(to_string(IterativeSolverMemory::lean))) {
      memory = IterativeSolverMemory::lean;
    } else if (argv[5] != std::string(to_string(IterativeSolverMemory::fast))) {
      std::fprintf(stderr, "fem_mpi_run: unknown iterative solver memory '%s'\n", argv[5]);
      return 2;
    }
  }
  std::vector<double> means;
  int rank = 0, n_ranks = 1;
  {
    testing::TubeCase tube("st venant kirchhoff", EndCondition::held_ends);
    FemParameters parameters;
    parameters.linear_solver = solver;
    parameters.iterative_solver_memory = memory;
    parameters.element_degree = degree;
    FemBackend backend(tube.problem, parameters);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &n_ranks);
    int index = 0;
    for (const double alpha : {1.2, 1.35, 1.5, 1.65, 1.8}) {
      tube.grow_to(alpha);
      if (index == 0) backend.set_positions(tube.placed(alpha * tube.rest_radius_m));
      const StepReport report = backend.solve({index++, alpha, false});
      means.push_back(tube.pressure(backend.state()).mean_Pa);
      if (rank == 0)
        std::printf("degree %d, %d ranks, alpha %.2f: p_mean %.12e Pa, %.3f s | %s\n", degree,
                    n_ranks, alpha, means.back(), report.wall_seconds, report.detail.c_str());
    }
  }
  int status = 0;
  if (mode == "write") {
    if (rank == 0) {
      std::ofstream out(file);
      out.precision(17);
      for (double p : means) out << p << "\n";
    }
  } else {
    std::ifstream in(file);
    for (double p : means) {
      double serial = 0.0;
      if (!(in >> serial)) {
        status = 1;
        break;
      }
      const double relative = std::abs(p / serial - 1.0);
      if (rank == 0) std::printf("serial %.12e Pa, relative difference %.2e\n", serial, relative);
      if (!(relative <= 1e-8)) status = 1;
    }
  }
  return status;
}
