#include "fem/mesh_part.h"

#include "fem/panel_triangles.h"
#include "fem/pattern_partition.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace tightfit {

namespace {

constexpr int part_tag = 7301;

// Rank 0: the part of `rank`, its own triangles and those sharing a panel vertex with one.
std::vector<MeshPartTriangle> part_of(const SimulationMesh& mesh,
                                      const std::vector<Triangle>& panel_triangles,
                                      const std::vector<unsigned int>& partition,
                                      unsigned int rank) {
  std::vector<char> own_corner(mesh.n_unwelded_vertices(), 0);
  for (std::size_t t = 0; t < panel_triangles.size(); ++t)
    if (partition[t] == rank)
      for (const int u : panel_triangles[t]) own_corner[u] = 1;
  std::vector<MeshPartTriangle> part;
  for (std::size_t t = 0; t < panel_triangles.size(); ++t) {
    const Triangle& corners = panel_triangles[t];
    if (std::none_of(corners.begin(), corners.end(), [&](int u) { return own_corner[u] != 0; }))
      continue;
    MeshPartTriangle triangle;
    triangle.index = static_cast<int>(t);
    triangle.rank = partition[t];
    triangle.panel = mesh.triangle_panel[t];
    triangle.welded = mesh.triangles[t];
    triangle.unwelded = corners;
    for (int k = 0; k < 3; ++k) triangle.layout_m[k] = mesh.layout_positions_m[corners[k]];
    triangle.rest_m = mesh.rest_triangles[t];
    part.push_back(triangle);
  }
  return part;
}

template <typename T>
void broadcast_vector(std::vector<T>& values, MPI_Comm comm) {
  static_assert(std::is_trivially_copyable_v<T>, "broadcast_vector: plain values only");
  unsigned long long size = values.size();
  MPI_Bcast(&size, 1, MPI_UNSIGNED_LONG_LONG, 0, comm);
  values.resize(size);
  MPI_Bcast(values.data(), static_cast<int>(size * sizeof(T)), MPI_BYTE, 0, comm);
}

// Rank 0's constraints on every rank: a vertex list per held group (a few rows of vertices).
void broadcast_constraints(std::vector<VertexConstraint>& constraints, MPI_Comm comm) {
  int n = static_cast<int>(constraints.size());
  MPI_Bcast(&n, 1, MPI_INT, 0, comm);
  constraints.resize(n);
  for (VertexConstraint& c : constraints) {
    int kind = static_cast<int>(c.kind);
    MPI_Bcast(&kind, 1, MPI_INT, 0, comm);
    c.kind = static_cast<VertexConstraint::Kind>(kind);
    std::vector<char> group(c.group.begin(), c.group.end());
    broadcast_vector(group, comm);
    c.group.assign(group.begin(), group.end());
    broadcast_vector(c.vertices, comm);
    MPI_Bcast(c.direction.data(), 3, MPI_DOUBLE, 0, comm);
  }
}

}  // namespace

const MeshPartTriangle& SimulationMeshPart::triangle(int t) const {
  const auto it = std::lower_bound(
      triangles.begin(), triangles.end(), t,
      [](const MeshPartTriangle& triangle, int index) { return triangle.index < index; });
  if (it == triangles.end() || it->index != t)
    throw std::logic_error("mesh part: triangle " + std::to_string(t) + " is not in this part");
  return *it;
}

SimulationMeshPart scatter_mesh_part(const Problem& problem, MPI_Comm comm) {
  int rank = 0, n_ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &n_ranks);
  int has_mesh = rank == 0 && problem.mesh != nullptr ? 1 : 0;
  MPI_Bcast(&has_mesh, 1, MPI_INT, 0, comm);
  if (!has_mesh)
    throw std::invalid_argument("fem backend: the problem needs a mesh (on rank 0 at least)");

  SimulationMeshPart part;
  std::array<double, 5> scalars{};
  if (rank == 0) {
    const SimulationMesh& mesh = *problem.mesh;
    double edge_sum = 0.0;
    for (const auto& r : mesh.rest_triangles)
      edge_sum += (r[1] - r[0]).norm() + (r[2] - r[1]).norm() + (r[0] - r[2]).norm();
    scalars = {double(mesh.n_vertices), double(mesh.triangles.size()), rest_area(mesh),
               mean_rest_edge_length_m(mesh), edge_sum / (3.0 * mesh.rest_triangles.size())};
    part.constraints = problem.constraints;
  }
  MPI_Bcast(scalars.data(), static_cast<int>(scalars.size()), MPI_DOUBLE, 0, comm);
  part.n_vertices = static_cast<int>(scalars[0]);
  part.n_triangles = static_cast<int>(scalars[1]);
  part.rest_area_m2 = scalars[2];
  part.mean_rest_edge_m = scalars[3];
  part.mean_triangle_edge_m = scalars[4];
  broadcast_constraints(part.constraints, comm);

  // A record is sent as one element of bytes, so that a message counts records, not bytes.
  MPI_Datatype record;
  MPI_Type_contiguous(sizeof(MeshPartTriangle), MPI_BYTE, &record);
  MPI_Type_commit(&record);
  if (rank == 0) {
    const SimulationMesh& mesh = *problem.mesh;
    const std::vector<Triangle> panel_triangles = unwelded_triangles(mesh);
    const std::vector<unsigned int> partition = partition_triangles(mesh, n_ranks);
    for (int r = 1; r < n_ranks; ++r) {
      const std::vector<MeshPartTriangle> sent = part_of(mesh, panel_triangles, partition, r);
      MPI_Send(sent.data(), static_cast<int>(sent.size()), record, r, part_tag, comm);
    }
    part.triangles = part_of(mesh, panel_triangles, partition, 0);
  } else {
    MPI_Status status;
    MPI_Probe(0, part_tag, comm, &status);
    int count = 0;
    MPI_Get_count(&status, record, &count);
    part.triangles.resize(count);
    MPI_Recv(part.triangles.data(), count, record, 0, part_tag, comm, MPI_STATUS_IGNORE);
  }
  MPI_Type_free(&record);
  return part;
}

std::vector<Vec3> layout_start_on_every_rank(const SimulationMesh* mesh, int n_vertices,
                                             MPI_Comm comm) {
  std::vector<Vec3> flat(n_vertices, Vec3::Zero());
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if (rank == 0)
    for (int u = 0; u < mesh->n_unwelded_vertices(); ++u)
      flat[mesh->welded_index[u]] =
          Vec3(mesh->layout_positions_m[u].x(), mesh->layout_positions_m[u].y(), 0);
  MPI_Bcast(reinterpret_cast<double*>(flat.data()), 3 * n_vertices, MPI_DOUBLE, 0, comm);
  return flat;
}

}  // namespace tightfit
