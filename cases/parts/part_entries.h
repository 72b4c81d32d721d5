// Every scenario part built into tightfit, one function per file of cases/parts/. A new part
// is a new file defining its entry and one line here and in cases/scenario_parts.cc
// (docs/scenarios.md).
#pragma once

#include "cases/case_parameters.h"
#include "cases/part_registry.h"
#include "core/dressing_stage.h"

namespace tightfit {

// Garments (Garment/Kind).
PartEntry<GarmentMaker> tube_garment_entry();
PartEntry<GarmentMaker> tapered_tube_garment_entry();
PartEntry<GarmentMaker> limb_tube_garment_entry();
PartEntry<GarmentMaker> sheet_garment_entry();
PartEntry<GarmentMaker> pattern_file_garment_entry();

// Bodies (Body/Kind).
PartEntry<BodyMaker> cylinder_body_entry();
PartEntry<BodyMaker> plane_body_entry();
PartEntry<BodyMaker> cone_body_entry();
PartEntry<BodyMaker> mesh_body_entry();
PartEntry<BodyMaker> morph_body_entry();

// Placements (Placement/Kind).
PartEntry<PlacementMaker> tube_round_cylinder_placement_entry();
PartEntry<PlacementMaker> flat_on_plane_placement_entry();
PartEntry<PlacementMaker> tube_round_axis_placement_entry();
PartEntry<PlacementMaker> dressing_placement_entry();
PartEntry<PlacementMaker> pattern_arrangement_placement_entry();
PartEntry<PlacementMaker> arrangement_placement_entry();
PartEntry<PlacementMaker> from_file_placement_entry();

// The dressing stage's frame counts (core/dressing_stage.h), shared by the placements that
// dress: Growth frames, Seam ramp frames, Maximum frames.
void declare_dressing_frames(ParameterTree& prm);
void read_dressing_frames(ParameterTree& prm, DressingSettings& settings);

// Measurements (Measurements/List).
PartEntry<MeasurementMaker> cylinder_theory_measurement_entry();
PartEntry<MeasurementMaker> angular_profile_measurement_entry();
PartEntry<MeasurementMaker> weight_on_plane_measurement_entry();
PartEntry<MeasurementMaker> air_pack_sensors_measurement_entry();
PartEntry<MeasurementMaker> stamps_measurement_entry();
PartEntry<MeasurementMaker> regions_measurement_entry();
PartEntry<MeasurementMaker> pictures_measurement_entry();
PartEntry<MeasurementMaker> compression_class_measurement_entry();

}  // namespace tightfit
