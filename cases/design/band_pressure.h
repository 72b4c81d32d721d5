// The mean and peak pressure over each measuring point's band of a garment (docs/design.md,
// "The method"): the part of the garment whose rest height along it (m from its bottom edge) lies
// within half a band width of the point's (cases/region_pressure.h: the area-weighted mean over
// the contact area, the largest vertex pressure). The band is a slab along the limb's axis `a`
// in the garment's worn shape with each vertex's axial coordinate replaced by its rest height,
// x' = x - (a.x) a + H a: a garment held along the limb keeps each rest height at its place on
// the axis, so this is the slab normal to the axis round the point.
#pragma once

#include "cases/design/design_loop.h"
#include "cases/step_measurement.h"

#include <vector>

namespace tightfit {

// Each band [H - width / 2, H + width / 2] of `heights_m` round the unit `axis`. `m` must
// hold its per-vertex arrays (the last step of a run, on the first rank).
std::vector<BandPressure> band_pressures(const SimulationMesh& mesh, const StepMeasurement& m,
                                         const std::vector<double>& heights_m, double band_width_m,
                                         const Vec3& axis);

}  // namespace tightfit
