// The pattern mesh split over the ranks (`mpirun -np N pattern_mesh_mpi_check [DEGREE]`): every
// panel triangle is the own cell of exactly one rank; every node is owned by exactly one rank
// and has one copy per panel it lies in, as the welded mesh counts them; the nodes' rest areas,
// each summed over the ranks' cells by the node copies' exchange, add up to the two 18.78 cm x
// 24 cm panels' area; the DoFs are whole node blocks and number every panel vertex (and panel
// edge) once; with quadratic triangles, each cell's corners are its triangle's. Exits non-zero
// on the first failed check.
#include "fem/pattern_mesh.h"
#include "tube_problem.h"

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <set>
#include <string>
#include <vector>

namespace {

int failures = 0;

void check(bool ok, const std::string& what) {
  if (!ok) {
    std::fprintf(stderr, "pattern_mesh_mpi_check: %s\n", what.c_str());
    ++failures;
  }
}

}  // namespace

int main(int argc, char** argv) {
  using namespace tightfit;
  dealii::Utilities::MPI::MPI_InitFinalize runtime(argc, argv, 1);
  const int degree = argc >= 2 ? std::stoi(argv[1]) : 1;
  const MPI_Comm comm = MPI_COMM_WORLD;
  const int rank = static_cast<int>(dealii::Utilities::MPI::this_mpi_process(comm));
  const testing::TubeCase tube("st venant kirchhoff", EndCondition::held_ends);
  const SimulationMesh& mesh = tube.mesh;
  const PatternMesh pattern(tube.problem, degree, comm);

  // Each triangle an own cell of one rank.
  std::vector<int> own(mesh.triangles.size(), 0), owners(mesh.triangles.size(), 0);
  for (const int t : pattern.cell_index) ++own[t];
  dealii::Utilities::MPI::sum(own, comm, owners);
  check(pattern.n_all_cells() == static_cast<int>(mesh.triangles.size()),
        "the cells of all ranks are not the mesh's triangles");
  check(std::all_of(owners.begin(), owners.end(), [](int n) { return n == 1; }),
        "a triangle is not the own cell of exactly one rank");

  // Each node owned once; a welded vertex's copies are its panel vertices.
  check(dealii::Utilities::MPI::sum(pattern.n_owned_nodes(), comm) == pattern.n_nodes(),
        "the owned nodes of all ranks are not every node once");
  std::vector<int> panel_copies(mesh.n_vertices, 0);
  for (const int w : mesh.welded_index) ++panel_copies[w];
  for (int node = 0; node < pattern.n_local_nodes(); ++node) {
    const int global = pattern.global_node(node);
    if (global < mesh.n_vertices)
      check(static_cast<int>(pattern.copies(node).size()) == panel_copies[global],
            "vertex " + std::to_string(global) + " has " +
                std::to_string(pattern.copies(node).size()) + " copies, not " +
                std::to_string(panel_copies[global]));
  }

  // The rest areas: two panels of 18.78 cm x 24 cm (to roundoff: measured 2e-14 relative with
  // either degree on 1 to 3 ranks; 1e-12 allowed).
  const std::vector<double> area_m2 = pattern.node_rest_area_m2();
  double total_m2 = 0.0;
  for (const double a : area_m2) total_m2 += a;
  const double panels_m2 = 2 * 0.1878 * 0.24;
  check(std::abs(total_m2 - panels_m2) <= 1e-12 * panels_m2,
        "the nodes' rest areas sum to " + std::to_string(total_m2) + " m^2, not " +
            std::to_string(panels_m2));

  // DoFs: three per panel vertex (and panel edge's midpoint: a seam edge has one in each
  // panel), in node blocks.
  std::size_t expected_nodes = mesh.n_unwelded_vertices();
  if (degree == 2) {
    std::set<std::array<int, 3>> panel_edges;  // (panel, welded ends)
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      for (int k = 0; k < 3; ++k) {
        std::array<int, 3> edge{mesh.triangle_panel[t], mesh.triangles[t][k],
                                mesh.triangles[t][(k + 1) % 3]};
        std::sort(edge.begin() + 1, edge.end());
        panel_edges.insert(edge);
      }
    expected_nodes += panel_edges.size();
  }
  check(pattern.n_dofs() == 3 * expected_nodes, std::to_string(pattern.n_dofs()) +
                                                    " DoFs, not 3 per panel node (" +
                                                    std::to_string(3 * expected_nodes) + ")");
  check(pattern.dofs_in_node_blocks, "a node's DoFs are not one block of 3");

  if (degree == 2)
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      std::array<int, 3> cell = pattern.cell_vertices[t], triangle = mesh.triangles[t];
      std::sort(cell.begin(), cell.end());
      std::sort(triangle.begin(), triangle.end());
      check(cell == triangle, "cell " + std::to_string(t) + "'s corners are not its triangle's");
    }

  const int all_failures = dealii::Utilities::MPI::sum(failures, comm);
  if (rank == 0)
    std::printf("%u ranks, degree %d: %d cells, %d nodes, %u DoFs, rest area %.15g m^2: %s\n",
                dealii::Utilities::MPI::n_mpi_processes(comm), degree, pattern.n_all_cells(),
                pattern.n_nodes(), pattern.n_dofs(), total_m2, all_failures ? "FAILED" : "ok");
  return all_failures == 0 ? 0 : 1;
}
