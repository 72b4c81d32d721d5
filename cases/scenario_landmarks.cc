#include "cases/scenario_landmarks.h"

#include "cases/scenario.h"

namespace tightfit {

TriangleSurface scenario_body_surface(const ScenarioBody& body) {
  const DisplayMesh mesh = body.body().display_mesh();
  TriangleSurface surface;
  surface.vertices_m = mesh.vertices_m;
  surface.triangles = mesh.triangles;
  return surface;
}

void resolve_named_regions(std::vector<BodyRegion>& regions, const Scenario& scenario) {
  if (!has_named_shapes(regions)) return;
  BodyMeasurements body;
  try {
    body = measure_body(scenario_body_surface(*scenario.body));
  } catch (const BodyMeasureError& e) {
    throw BodyMeasureError(std::string("Measurements/Regions: the named regions need the body's "
                                       "landmarks: ") +
                           e.what());
  }
  resolve_named_regions(regions, body);
}

}  // namespace tightfit
