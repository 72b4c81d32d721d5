#include "cases/scenario_landmarks.h"

#include "cases/scenario.h"

namespace tightfit {

void resolve_named_regions(std::vector<BodyRegion>& regions, const Scenario& scenario) {
  if (!has_named_shapes(regions)) return;
  const DisplayMesh mesh = scenario.body->body().display_mesh();
  TriangleSurface surface;
  surface.vertices_m = mesh.vertices_m;
  surface.triangles = mesh.triangles;
  BodyMeasurements body;
  try {
    body = measure_body(surface);
  } catch (const BodyMeasureError& e) {
    throw BodyMeasureError(std::string("Measurements/Regions: the named regions need the body's "
                                       "landmarks: ") +
                           e.what());
  }
  resolve_named_regions(regions, body);
}

}  // namespace tightfit
