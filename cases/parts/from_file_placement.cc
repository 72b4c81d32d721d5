// Placement/Kind = from file: the garment where another run left it, read from a garment VTU
// that run wrote (garment_NNNN.vtu). The garment must be the same mesh (the same case's
// garment and mesh settings): its points are taken as this case's start, so that a state one
// backend reached (a dressed and settled top) starts the other (docs/cases.md "Starting from a
// previous run").
#include "bodies/surface_return.h"
#include "cases/parts/part_entries.h"
#include "cases/scenario.h"
#include "io/triangle_vtu_reader.h"

#include <sstream>
#include <stdexcept>

namespace tightfit {

namespace {

// The file's triangles must be this case's, corner for corner: the same count of points is not
// enough (another garment of the same size would pass).
void check_same_mesh(const std::string& path, const TriangleGrid& grid,
                     const SimulationMesh& mesh) {
  std::ostringstream message;
  message << "Placement/From file/File = '" << path << "': ";
  const bool same_size = static_cast<int>(grid.points_m.size()) == mesh.n_vertices &&
                         grid.triangles.size() == mesh.triangles.size();
  if (!same_size) {
    message << "it holds " << grid.points_m.size() << " points and " << grid.triangles.size()
            << " triangles, this case's garment mesh " << mesh.n_vertices << " and "
            << mesh.triangles.size()
            << " (a file written by a run of another garment or mesh size)";
    throw std::invalid_argument(message.str());
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    if (grid.triangles[t] != mesh.triangles[t]) {
      message << "its triangle " << t << " joins points " << grid.triangles[t][0] << ", "
              << grid.triangles[t][1] << ", " << grid.triangles[t][2] << ", this case's "
              << mesh.triangles[t][0] << ", " << mesh.triangles[t][1] << ", "
              << mesh.triangles[t][2] << " (a file written by a run of another garment)";
      throw std::invalid_argument(message.str());
    }
}

}  // namespace

PartEntry<PlacementMaker> from_file_placement_entry() {
  PartEntry<PlacementMaker> e;
  e.name = "from file";
  e.subsection = "From file";
  e.description =
      "the garment's positions read from a garment VTU an earlier run of the same garment wrote "
      "(docs/cases.md).";
  e.declare_parameters = [](ParameterTree& prm) {
    prm.declare_text("File", "",
                     "A garment_NNNN.vtu written by a run of the same garment and mesh settings "
                     "(any backend, one process); a relative path is read from the working "
                     "directory, else from the case file's folder.");
    prm.declare_double("Largest depth", 0.25, 0, ParameterTree::unbounded,
                       "Points inside the body by at most this fraction of the mean rest edge "
                       "length (the penalty's own depth) are put back onto its surface; a deeper "
                       "one stops the case (-).");
  };
  e.parse = [](ParameterTree& prm) -> PlacementMaker {
    const std::string path = prm.get_file_name("File");
    const double depth_fraction = prm.get_double("Largest depth");
    if (path.empty())
      throw std::invalid_argument("Placement/From file/File is empty: name a garment VTU");
    return [=](const Scenario& scenario) {
      TriangleGrid grid = read_triangle_vtu(path);
      check_same_mesh(path, grid, scenario.mesh);
      const double allowed_m = depth_fraction * scenario.mean_edge_length_m;
      const SurfaceReturn back =
          return_onto_surface(scenario.body->body(), grid.points_m, allowed_m);
      if (back.deepest_m > allowed_m) {
        const Vec3& p = grid.points_m[back.deepest_point];
        std::ostringstream message;
        message << "Placement/From file/File = '" << path << "': point " << back.deepest_point
                << " at (" << p.x() << ", " << p.y() << ", " << p.z() << ") m lies "
                << back.deepest_m << " m inside the body (" << scenario.body->describe()
                << "), more than " << allowed_m
                << " m: the file was written on another body, or at another size of it";
        throw std::invalid_argument(message.str());
      }
      return grid.points_m;
    };
  };
  return e;
}

}  // namespace tightfit
