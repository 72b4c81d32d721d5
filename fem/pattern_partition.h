// The pattern's cells split over the MPI ranks, and the part of the finite-element mesh each
// rank builds for itself: its own cells and one layer of other ranks' cells round them, so that
// no rank ever holds a triangulation of every cell (deal.II's fully distributed triangulation).
#pragma once

#include "core/garment.h"

#include <deal.II/grid/tria_description.h>

#include <mpi.h>

#include <vector>

namespace tightfit {

// Each panel triangle's rank, the same on every rank (collective): METIS on the graph of
// triangles sharing a welded edge (so that a seam's two sides tend to fall on one rank), run on
// rank 0 and broadcast. On one rank, every triangle is its.
std::vector<unsigned int> partition_triangles(const SimulationMesh& mesh, MPI_Comm comm);

// This rank's part of the pattern as a fully distributed triangulation's description: the
// triangles `partition` gives it, and as ghosts those of other ranks sharing a vertex with one of
// them (the layer deal.II needs to number the DoFs on the partition's boundary). Cell t of
// `panel_triangles` (unwelded corners) is coarse cell t, its corners in the same order, its
// material id its panel.
dealii::TriangulationDescription::Description<2, 2> own_cells_description(
    const SimulationMesh& mesh, const std::vector<Triangle>& panel_triangles,
    const std::vector<unsigned int>& partition, MPI_Comm comm);

}  // namespace tightfit
