// The scenario parts built into tightfit, by kind (cases/parts/, docs/scenarios.md).
#pragma once

#include "cases/case_parameters.h"
#include "cases/part_registry.h"

namespace tightfit {

const PartRegistry<GarmentMaker>& garment_kinds();          // Garment/Kind
const PartRegistry<BodyMaker>& body_kinds();                // Body/Kind
const PartRegistry<PlacementMaker>& placement_kinds();      // Placement/Kind
const PartRegistry<MeasurementMaker>& measurement_kinds();  // Measurements/List

}  // namespace tightfit
