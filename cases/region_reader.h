// The pressure by named region as the regions measurement reads it (Measurements/List:
// regions; cases/parts/regions_measurement.cc), for a caller that needs the values themselves
// and not only regions.csv: a convergence study reads every level's regions through it
// (cases/convergence_run.h).
#pragma once

#include "cases/body_region.h"
#include "cases/region_pressure.h"

#include <memory>
#include <vector>

namespace tightfit {

struct Scenario;
struct StepMeasurement;
struct CaseParameters;
class Measurement;

class RegionReader {
 public:
  virtual ~RegionReader() = default;
  // The case's regions in the order of Regions/Definitions; their named shapes are resolved
  // once the measurement is prepared on a scenario (Measurement::prepare).
  virtual const std::vector<BodyRegion>& regions() const = 0;
  // Each region's pressure at one step whose per-vertex arrays are held, in regions()' order.
  virtual std::vector<RegionPressure> region_pressures(const Scenario& scenario,
                                                       const StepMeasurement& step) const = 0;
};

// A fresh copy of the case's regions measurement (`reader` points into `measurement`), or two
// nulls when Measurements/List does not list regions.
struct CaseRegions {
  std::unique_ptr<Measurement> measurement;
  RegionReader* reader = nullptr;
};
CaseRegions make_case_regions(const CaseParameters& parameters);

}  // namespace tightfit
