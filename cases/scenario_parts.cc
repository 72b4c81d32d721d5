// The registrations: one line per part of cases/parts/.
#include "cases/scenario_parts.h"

#include "cases/parts/part_entries.h"

#include <filesystem>

namespace tightfit {

const PartRegistry<GarmentMaker>& garment_kinds() {
  static const PartRegistry<GarmentMaker> registry = [] {
    PartRegistry<GarmentMaker> r("Garment");
    r.add(tube_garment_entry());
    r.add(tapered_tube_garment_entry());
    r.add(limb_tube_garment_entry());
    r.add(sheet_garment_entry());
    r.add(pattern_file_garment_entry());
    return r;
  }();
  return registry;
}

const PartRegistry<BodyMaker>& body_kinds() {
  static const PartRegistry<BodyMaker> registry = [] {
    PartRegistry<BodyMaker> r("Body");
    r.add(cylinder_body_entry());
    r.add(plane_body_entry());
    r.add(cone_body_entry());
    r.add(mesh_body_entry());
    r.add(morph_body_entry());
    return r;
  }();
  return registry;
}

const PartRegistry<PlacementMaker>& placement_kinds() {
  static const PartRegistry<PlacementMaker> registry = [] {
    PartRegistry<PlacementMaker> r("Placement");
    r.add(tube_round_cylinder_placement_entry());
    r.add(flat_on_plane_placement_entry());
    r.add(tube_round_axis_placement_entry());
    r.add(dressing_placement_entry());
    r.add(pattern_arrangement_placement_entry());
    r.add(arrangement_placement_entry());
    r.add(from_file_placement_entry());
    return r;
  }();
  return registry;
}

const PartRegistry<MeasurementMaker>& measurement_kinds() {
  static const PartRegistry<MeasurementMaker> registry = [] {
    PartRegistry<MeasurementMaker> r("Measurements");
    r.add(cylinder_theory_measurement_entry());
    r.add(angular_profile_measurement_entry());
    r.add(weight_on_plane_measurement_entry());
    r.add(air_pack_sensors_measurement_entry());
    r.add(stamps_measurement_entry());
    r.add(regions_measurement_entry());
    r.add(pictures_measurement_entry());
    r.add(compression_class_measurement_entry());
    return r;
  }();
  return registry;
}

std::string RunFiles::path(const std::string& file_name) const {
  return (std::filesystem::path(directory) / file_name).string();
}

}  // namespace tightfit
