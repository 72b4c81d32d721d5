// A rank's part of the garment's SimulationMesh, sent from rank 0: the FE backend's setup reads
// only this, so that no other rank needs the whole mesh (Problem::mesh may be null there).
//
// Rank 0 partitions the panel triangles (pattern_partition.h) and sends each rank its own
// triangles and, as ghosts, those of other ranks sharing a panel vertex with one of them (the
// layer a fully distributed triangulation needs), each with what the setup reads of it in the
// global numbering, and broadcasts the few whole-mesh numbers and the vertex constraints. The
// ranks receive their parts one after the other, so that rank 0 holds one part at a time
// besides the mesh. On one rank, the part is every triangle.
#pragma once

#include "core/backend.h"
#include "core/garment.h"

#include <mpi.h>

#include <array>
#include <vector>

namespace tightfit {

// One triangle of a rank's part, as the setup reads it (sent as bytes: fixed-size members).
struct MeshPartTriangle {
  int index = 0;          // its index in SimulationMesh::triangles (the cell's coarse id)
  unsigned int rank = 0;  // the rank whose own cell it is
  int panel = 0;          // SimulationMesh::triangle_panel
  Triangle welded{};      // SimulationMesh::triangles[index]
  // The panel (unwelded) vertices of the same corners (panel_triangles.h), and their positions
  // in the layout plane, m.
  Triangle unwelded{};
  std::array<Vec2, 3> layout_m{};
  std::array<Vec2, 3> rest_m{};  // SimulationMesh::rest_triangles[index], grain axes, m
};

struct SimulationMeshPart {
  // Of the whole mesh.
  int n_vertices = 0;
  int n_triangles = 0;
  double rest_area_m2 = 0.0;      // rest_area
  double mean_rest_edge_m = 0.0;  // mean_rest_edge_length_m: each edge once
  // The mean over the triangles' three edges (an interior edge counted twice), m.
  double mean_triangle_edge_m = 0.0;
  std::vector<VertexConstraint> constraints;  // rank 0's Problem::constraints
  // This rank's own triangles and their ghosts, ascending by index.
  std::vector<MeshPartTriangle> triangles;

  // The triangle of global index t (it must be in the part).
  const MeshPartTriangle& triangle(int t) const;
};

// Collective over `comm`: each rank's part of `problem.mesh` as rank 0 holds it (other ranks'
// Problem::mesh and constraints are not read). Throws std::invalid_argument on every rank
// when rank 0 has no mesh.
SimulationMeshPart scatter_mesh_part(const Problem& problem, MPI_Comm comm);

// Every welded vertex at its position in the layout plane (z = 0), as rank 0's mesh gives it
// (the last panel copy of a seam vertex), on every rank (collective).
std::vector<Vec3> layout_start_on_every_rank(const SimulationMesh* mesh, int n_vertices,
                                             MPI_Comm comm);

}  // namespace tightfit
