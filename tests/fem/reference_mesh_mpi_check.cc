// The reference mesh split over the ranks (`mpirun -np N reference_mesh_mpi_check [DEGREE
// [mesh-on-rank-0]]`): every panel triangle is the own cell of exactly one rank; every node is
// owned by exactly one rank and has one copy per panel it lies in, as the welded mesh counts
// them; the nodes' rest areas, each summed over the ranks' cells by the node copies' exchange,
// and their contact areas add up to the two 18.78 cm x 24 cm panels' area; the DoFs are whole
// node blocks and number every panel vertex (and panel edge) once; with quadratic triangles,
// each cell's corners are its triangle's. With `mesh-on-rank-0` the pattern is built from a
// problem that has the mesh and the held ends on rank 0 only (the check itself reads the mesh on
// every rank). Exits non-zero on the first failed check.
#include "fem/reference_mesh.h"
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
    std::fprintf(stderr, "reference_mesh_mpi_check: %s\n", what.c_str());
    ++failures;
  }
}

}  // namespace

int main(int argc, char** argv) {
  using namespace tightfit;
  dealii::Utilities::MPI::MPI_InitFinalize runtime(argc, argv, 1);
  const int degree = argc >= 2 ? std::stoi(argv[1]) : 1;
  const bool mesh_on_rank_0 = argc >= 3 && argv[2] == std::string("mesh-on-rank-0");
  const MPI_Comm comm = MPI_COMM_WORLD;
  const int rank = static_cast<int>(dealii::Utilities::MPI::this_mpi_process(comm));
  const testing::TubeCase tube("st venant kirchhoff", EndCondition::held_ends);
  const SimulationMesh& mesh = tube.mesh;
  Problem problem = tube.problem;
  if (mesh_on_rank_0 && rank > 0) {
    problem.mesh = nullptr;
    problem.constraints.clear();
  }
  const ReferenceMesh pattern(problem, degree, comm);

  // Each triangle an own cell of one rank.
  std::vector<int> own(mesh.triangles.size(), 0), owners(mesh.triangles.size(), 0);
  for (const int t : pattern.cell_index()) ++own[t];
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

  // The contact areas (a third of each triangle's rest area at its corners; with degree 2 a
  // twelfth, and a quarter at each edge's midpoint) and the edge lengths of the owned nodes;
  // the constrained nodes: the held rows' vertices, whichever rank holds the mesh. The contact
  // areas' sum: measured within 7e-15 relative with either degree on 1 to 3 ranks; 1e-12 allowed.
  double contact_m2 = 0.0;
  int n_constrained = 0;
  for (const int node : pattern.owned_nodes()) {
    contact_m2 += pattern.node_contact_area_m2()[node];
    check(pattern.node_edge_m()[node] > 0.0,
          "node " + std::to_string(pattern.global_node(node)) + " has no edge length");
    n_constrained += pattern.node_constrained().constrained(node);
  }
  contact_m2 = dealii::Utilities::MPI::sum(contact_m2, comm);
  check(std::abs(contact_m2 - panels_m2) <= 1e-12 * panels_m2,
        "the nodes' contact areas sum to " + std::to_string(contact_m2) + " m^2, not " +
            std::to_string(panels_m2));
  std::set<int> held;
  for (const VertexConstraint& c : tube.problem.constraints)
    held.insert(c.vertices.begin(), c.vertices.end());
  // With degree 2, the midpoints of the held rows' edges are held too.
  std::size_t expected_held = held.size();
  for (const auto& ends : pattern.edge_ends())
    expected_held += held.count(ends[0]) && held.count(ends[1]);
  check(dealii::Utilities::MPI::sum(n_constrained, comm) == static_cast<int>(expected_held),
        "the constrained nodes are not the held rows' " + std::to_string(expected_held));

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
  check(pattern.dofs_in_node_blocks(), "a node's DoFs are not one block of 3");

  if (degree == 2)
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      std::array<int, 3> cell = pattern.cell_vertices()[t], triangle = mesh.triangles[t];
      std::sort(cell.begin(), cell.end());
      std::sort(triangle.begin(), triangle.end());
      check(cell == triangle, "cell " + std::to_string(t) + "'s corners are not its triangle's");
    }

  const int all_failures = dealii::Utilities::MPI::sum(failures, comm);
  if (rank == 0)
    std::printf(
        "%u ranks, degree %d%s: %d cells, %d nodes, %u DoFs, rest area %.15g m^2, contact area "
        "%.15g m^2: %s\n",
        dealii::Utilities::MPI::n_mpi_processes(comm), degree,
        mesh_on_rank_0 ? ", mesh on rank 0" : "", pattern.n_all_cells(), pattern.n_nodes(),
        pattern.n_dofs(), total_m2, contact_m2, all_failures ? "FAILED" : "ok");
  return all_failures == 0 ? 0 : 1;
}
