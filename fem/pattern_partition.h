// The pattern's cells split over the MPI ranks, and the part of the finite-element mesh each
// rank builds for itself: its own cells and one layer of other ranks' cells round them, so that
// no rank ever holds a triangulation of every cell (deal.II's fully distributed triangulation).
#pragma once

#include "core/garment.h"
#include "fem/mesh_part.h"

#include <deal.II/grid/tria_description.h>

#include <mpi.h>

#include <vector>

namespace tightfit {

// Each panel triangle's rank of `n_ranks`: METIS on the graph of triangles sharing a welded edge
// (so that a seam's two sides tend to fall on one rank). Run on rank 0, which sends each rank
// its part (mesh_part.h). On one rank, every triangle is its.
std::vector<unsigned int> partition_triangles(const SimulationMesh& mesh, int n_ranks);

// This rank's part of the pattern as a fully distributed triangulation's description: the
// part's own triangles, and as ghosts the others (those of other ranks sharing a vertex with one
// of them, the layer deal.II needs to number the DoFs on the partition's boundary). Triangle t
// is coarse cell t, its unwelded corners in the same order, its material id its panel.
dealii::TriangulationDescription::Description<2, 2> own_cells_description(
    const SimulationMeshPart& part, MPI_Comm comm);

}  // namespace tightfit
