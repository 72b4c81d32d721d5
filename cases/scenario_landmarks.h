// The landmarks of a scenario's body (body/body_measurements.h), for the named regions of the
// measurements (cases/body_region.h).
#pragma once

#include "body/body_measurements.h"
#include "cases/body_region.h"

namespace tightfit {

struct Scenario;
class ScenarioBody;

// The body's closed surface as the scenario holds it (its display mesh: a mesh body's own
// triangles).
TriangleSurface scenario_body_surface(const ScenarioBody& body);

// Resolves the named shapes of `regions` on the scenario's body as it is now, if any; prints
// nothing. Throws BodyMeasureError naming the region and the landmark not found.
void resolve_named_regions(std::vector<BodyRegion>& regions, const Scenario& scenario);

}  // namespace tightfit
