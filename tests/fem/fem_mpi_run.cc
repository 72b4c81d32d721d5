// The 2-rank check: `fem_mpi_run write FILE` solves the 4 5T tube on the
// cylinder (St. Venant-Kirchhoff, held ends, alpha 1.2 - 1.8) and writes the mean pressures;
// `mpirun -np 2 fem_mpi_run compare FILE` solves the same case with the mesh and the solves
// distributed and fails unless every mean pressure equals the serial one to 1e-8 relative.
// `mpirun -np N fem_mpi_run compare-mesh-on-rank-0 FILE` does the same with the garment's mesh
// (and the held ends) on rank 0 only, the other ranks' problem without a mesh, and also solves
// with the mesh on every rank on the same ranks: the two runs must give the same mean pressures,
// nodal contact forces and membrane forces at every vertex (the same partition and the same
// data, so only the parallel sums' order between runs differs: measured 0 on 2 ranks and up to
// 2.6e-13 relative (the contact forces; 1.1e-14 the means) on 3, where two runs of the same
// differ as much; 1e-11 allowed).
// A third argument sets the element degree (1 by default), a fourth the linear solver by its
// parameter name (direct, MUMPS, by default; the reference is always written with it), a fifth
// `Finite elements/Iterative solver memory` (fast by default). An error (e.g. degree 2 with the
// mesh on rank 0 only) is printed and exits with status 1.
#include "fem/fem_backend.h"
#include "tube_problem.h"

#include <deal.II/base/mpi.h>

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace {

using namespace tightfit;

// Every step's mean pressure, and on rank 0 every node's contact force and every vertex's
// membrane force components, one after the other.
struct Run {
  std::vector<double> means, contact_N, internal_N;
};

Run solve_steps(testing::TubeCase& tube, const FemParameters& parameters) {
  Run run;
  FemBackend backend(tube.problem, parameters);
  int rank = 0, n_ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &n_ranks);
  int index = 0;
  for (const double alpha : {1.2, 1.35, 1.5, 1.65, 1.8}) {
    tube.grow_to(alpha);
    if (index == 0) backend.set_positions(tube.placed(alpha * tube.rest_radius_m));
    const StepReport report = backend.solve({index++, alpha, false});
    const SurfaceState state = backend.state();
    const std::vector<double> contact_N = backend.nodal_contact_force_N();
    double mean_Pa = rank == 0 ? tube.pressure(state).mean_Pa : 0.0;
    MPI_Bcast(&mean_Pa, 1, MPI_DOUBLE, 0, MPI_COMM_WORLD);
    run.means.push_back(mean_Pa);
    if (rank == 0) {
      run.contact_N.insert(run.contact_N.end(), contact_N.begin(), contact_N.end());
      for (const Vec3& f : state.internal_force_N)
        run.internal_N.insert(run.internal_N.end(), f.data(), f.data() + 3);
      std::printf("degree %d, %d ranks, alpha %.2f: p_mean %.12e Pa, %.3f s | %s\n",
                  parameters.element_degree, n_ranks, alpha, mean_Pa, report.wall_seconds,
                  report.text().c_str());
    }
  }
  return run;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace tightfit;
  if (argc < 3 || argc > 6) {
    std::fprintf(stderr,
                 "usage: fem_mpi_run write|compare|compare-mesh-on-rank-0 FILE "
                 "[ELEMENT_DEGREE [SOLVER [MEMORY]]]\n");
    return 2;
  }
  // MPI first: the mesh on rank 0 only is built knowing the rank.
  dealii::Utilities::MPI::MPI_InitFinalize runtime(argc, argv, 1);
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
  FemParameters parameters;
  parameters.linear_solver = solver;
  parameters.iterative_solver_memory = memory;
  parameters.element_degree = degree;
  int rank = 0;
  Run run, whole_mesh_run;
  try {
    if (mode == "compare-mesh-on-rank-0") {
      testing::TubeCase tube("st venant kirchhoff", EndCondition::held_ends, MeshSpacing{},
                             testing::MeshOnFirstRank{});
      run = solve_steps(tube, parameters);
      testing::TubeCase whole("st venant kirchhoff", EndCondition::held_ends);
      whole_mesh_run = solve_steps(whole, parameters);
    } else {
      testing::TubeCase tube("st venant kirchhoff", EndCondition::held_ends);
      run = solve_steps(tube, parameters);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fem_mpi_run: %s\n", e.what());
    return 1;
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const std::vector<double>& means = run.means;
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
  if (mode == "compare-mesh-on-rank-0") {
    // Largest difference relative to the largest value of each kind over every step.
    const auto relative = [](const std::vector<double>& a, const std::vector<double>& b) {
      if (a.size() != b.size()) return 1.0;
      double difference = 0.0, largest = 0.0;
      for (std::size_t k = 0; k < a.size(); ++k) {
        difference = std::max(difference, std::abs(a[k] - b[k]));
        largest = std::max(largest, std::abs(b[k]));
      }
      return largest > 0.0 ? difference / largest : difference;
    };
    const double d_mean = relative(run.means, whole_mesh_run.means);
    const double d_contact = relative(run.contact_N, whole_mesh_run.contact_N);
    const double d_internal = relative(run.internal_N, whole_mesh_run.internal_N);
    if (rank == 0)
      std::printf(
          "mesh on rank 0 only against the mesh on every rank: mean pressures %.2e, nodal "
          "contact forces %.2e, membrane forces %.2e relative\n",
          d_mean, d_contact, d_internal);
    if (!(std::max({d_mean, d_contact, d_internal}) <= 1e-11)) status = 1;
  }
  return status;
}
