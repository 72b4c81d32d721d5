#include "app/girths_command.h"

#include "bodies/surface_slice.h"
#include "cases/case_parameters.h"
#include "cases/scenario.h"
#include "cases/scenario_body.h"

#include <cstdio>
#include <ostream>

namespace tightfit {

int girths_command(const CommandLine& cl, std::ostream& out) {
  CaseFile file;
  file.read(cl.case_files.front(), cl.overrides);
  const CaseParameters parameters = file.parameters();
  const std::unique_ptr<ScenarioBody> body = make_case_body(parameters);
  body->morph(0, body->initial_alpha());
  const DisplayMesh mesh = body->body().display_mesh();
  TriangleSurface surface;
  surface.vertices_m = mesh.vertices_m;
  surface.triangles = mesh.triangles;
  const Vec3 axis = Vec3(cl.girths_axis[0], cl.girths_axis[1], cl.girths_axis[2]).normalized();
  const Vec3 near(cl.girths_near[0], cl.girths_near[1], cl.girths_near[2]);
  out << "Girths of " << body->describe() << "\nslices normal to (" << axis.x() << ", " << axis.y()
      << ", " << axis.z() << "), the loop round (" << near.x() << ", " << near.y() << ", "
      << near.z() << ") m\n\n";
  char line[200];
  std::snprintf(line, sizeof line, "%10s %12s %12s %12s   %s\n", "height [m]", "section [m]",
                "tape [m]", "area [m2]", "centroid x, y, z [m]");
  out << line;
  std::vector<Vec3> centroids;
  for (const double h : cl.girths_heights) {
    // Each slice looks for the loop round the near point moved to its own height.
    const SliceLoop loop = slice_surface(surface, axis, h, near + (h - axis.dot(near)) * axis);
    centroids.push_back(loop.centroid_m);
    std::snprintf(line, sizeof line, "%10.4f %12.4f %12.4f %12.6f   %.4f, %.4f, %.4f\n", h,
                  loop.perimeter_m, loop.hull_perimeter_m, loop.area_m2, loop.centroid_m.x(),
                  loop.centroid_m.y(), loop.centroid_m.z());
    out << line;
  }
  if (centroids.size() >= 2) {
    const Vec3 d = (centroids.back() - centroids.front()).normalized();
    std::snprintf(line, sizeof line,
                  "\naxis through the first and last centroids: direction %.4f, %.4f, %.4f "
                  "(%.2f deg from the slices' normal)\n",
                  d.x(), d.y(), d.z(), std::acos(std::min(1.0, d.dot(axis))) * 180 / M_PI);
    out << line;
  }
  return 0;
}

}  // namespace tightfit
