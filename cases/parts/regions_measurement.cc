// Measurements/List: regions. regions.csv: for every named region of the case
// (cases/body_region.h) and every load step, the contact area, the mean and peak pressure (Pa
// and mmHg) and the normal force, as cases/region_pressure.h defines them; on screen at the end
// of the run, the same for the last load step.
#include "cases/csv_measurement.h"
#include "cases/parts/part_entries.h"
#include "cases/region_pressure.h"
#include "cases/region_reader.h"
#include "cases/scenario_landmarks.h"
#include "cases/step_measurement.h"
#include "core/units.h"

namespace tightfit {

namespace {

// Why a region has no mean pressure: no garment there, or garment without contact.
std::string note(const RegionPressure& r) {
  if (r.n_contact_vertices > 0) return "";
  return r.garment_area_m2 > 0 ? "no contact" : "no garment in the region";
}

class RegionsMeasurement final : public CsvMeasurement, public RegionReader {
 public:
  explicit RegionsMeasurement(std::vector<BodyRegion> regions)
      : CsvMeasurement("regions.csv", {"step", "alpha", "region", "contact_area_m2", "p_mean_Pa",
                                       "p_peak_Pa", "p_mean_mmHg", "p_peak_mmHg", "normal_force_N",
                                       "n_contact_vertices", "garment_area_m2", "note"}),
        regions_(std::move(regions)) {}

  void prepare(const Scenario& scenario) override { resolve_named_regions(regions_, scenario); }

  const std::vector<BodyRegion>& regions() const override { return regions_; }
  std::vector<RegionPressure> region_pressures(const Scenario& scenario,
                                               const StepMeasurement& m) const override {
    std::vector<RegionPressure> pressures;
    for (const BodyRegion& region : regions_) pressures.push_back(measure(scenario, m, region));
    return pressures;
  }

  std::vector<TextTable> summary_tables(const Scenario& /*scenario*/,
                                        const std::vector<StepMeasurement>& steps) const override {
    if (steps.empty() || last_step_ != steps.back().step) return {};
    const StepMeasurement& m = steps.back();
    TextTable table("Pressure by region, load step " + std::to_string(m.step) + " (alpha " +
                        format_fixed(m.alpha, 3) + "); mean over the contact area",
                    {"region", "contact area [m2]", "p_mean [Pa]", "p_mean [mmHg]", "p_peak [Pa]",
                     "p_peak [mmHg]", "force [N]", "note"});
    for (std::size_t k = 0; k < regions_.size(); ++k) {
      const BodyRegion& region = regions_[k];
      const RegionPressure& r = last_[k];
      table.add_row({region.name, format_number(r.contact_area_m2, 4), format_fixed(r.mean_Pa, 2),
                     format_fixed(units::to_mmHg(r.mean_Pa), 3), format_fixed(r.peak_Pa, 2),
                     format_fixed(units::to_mmHg(r.peak_Pa), 3), format_number(r.normal_force_N, 4),
                     note(r)});
    }
    return {table};
  }

 protected:
  std::vector<std::vector<CsvCell>> rows(const Scenario& scenario,
                                         const StepMeasurement& m) override {
    std::vector<std::vector<CsvCell>> rows;
    last_ = region_pressures(scenario, m);
    last_step_ = m.step;
    for (std::size_t k = 0; k < regions_.size(); ++k) {
      const RegionPressure& r = last_[k];
      rows.push_back({m.step, m.alpha, regions_[k].name, r.contact_area_m2, r.mean_Pa, r.peak_Pa,
                      units::to_mmHg(r.mean_Pa), units::to_mmHg(r.peak_Pa), r.normal_force_N,
                      r.n_contact_vertices, r.garment_area_m2, note(r)});
    }
    return rows;
  }

 private:
  static RegionPressure measure(const Scenario& scenario, const StepMeasurement& m,
                                const BodyRegion& region) {
    return region_pressure(region, scenario.mesh.triangles, m.state.positions_m, m.field);
  }

  std::vector<BodyRegion> regions_;
  // The latest step's values, for the table on screen (the run keeps no step's field).
  std::vector<RegionPressure> last_;
  int last_step_ = -1;
};

}  // namespace

CaseRegions make_case_regions(const CaseParameters& parameters) {
  CaseRegions found;
  for (const NamedMeasurement& m : parameters.measurements)
    if (m.kind == "regions") {
      found.measurement = m.make();
      found.reader = dynamic_cast<RegionsMeasurement*>(found.measurement.get());
      break;
    }
  return found;
}

PartEntry<MeasurementMaker> regions_measurement_entry() {
  PartEntry<MeasurementMaker> e;
  e.name = "regions";
  e.subsection = "Regions";
  e.description =
      "regions.csv and a table on screen: contact area, mean and peak pressure (Pa, mmHg) and "
      "normal force in each named region of Regions/Definitions, every load step.";
  e.declare_parameters = [](ParameterTree& prm) {
    prm.declare_text(
        "Definitions", "",
        "Named regions of space, 'NAME: SHAPE [+ SHAPE ...]; NAME: ...', each the union of its "
        "shapes: 'slab AXIS LOW HIGH' (the points whose height along AXIS, one of x, y, z or a "
        "direction a,b,c, lies between LOW and HIGH, m), 'box XMIN,YMIN,ZMIN XMAX,YMAX,ZMAX' "
        "(m), 'ball X,Y,Z RADIUS' (m), or a region named by anatomy and built from the body's "
        "landmarks, 'NAMED [left|right] [front|back] [WIDTH]' with NAMED one of bust, "
        "under-bust band, waist band, hip band, scapulae, B, C, G, knee, calf, thigh (WIDTH, m, "
        "replaces its default). A garment vertex counts by the share of its area inside "
        "(docs/measurements.md).");
  };
  e.parse = [](ParameterTree& prm) -> MeasurementMaker {
    std::vector<BodyRegion> regions;
    try {
      regions = parse_body_regions(prm.get("Definitions"));
    } catch (const std::invalid_argument& error) {
      throw std::invalid_argument(std::string("Definitions: ") + error.what());
    }
    return [regions] { return std::make_unique<RegionsMeasurement>(regions); };
  };
  return e;
}

}  // namespace tightfit
