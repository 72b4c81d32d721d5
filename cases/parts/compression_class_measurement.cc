// Measurements/List: compression class. The RAL-GZ 387 compression class (cases/
// compression_class.h) a stocking's pressure at the ankle meets: the mean pressure over the
// contact area of one region of Measurements/Regions/Definitions (measuring point B), as the
// regions measurement defines it; columns in pressure.csv and a line on screen.
#include "cases/compression_class.h"
#include "cases/parts/part_entries.h"
#include "cases/region_pressure.h"
#include "cases/step_measurement.h"
#include "core/closest_names.h"
#include "core/units.h"

#include <cmath>
#include <limits>

namespace tightfit {

namespace {

class CompressionClassMeasurement final : public Measurement {
 public:
  explicit CompressionClassMeasurement(BodyRegion ankle) : ankle_(std::move(ankle)) {}

  std::vector<std::string> columns() const override {
    return {"ankle_p_mean_mmHg", "compression_class"};
  }
  std::vector<double> values(const Scenario& scenario, const StepMeasurement& m) const override {
    const double p = ankle_mmHg(scenario, m);
    return {p, std::isnan(p) ? p : ral_gz_387_class(p).number};
  }
  // The latest step's pressure, for the line on screen (the run keeps no step's field).
  void after_step(const Scenario& scenario, const StepMeasurement& m,
                  const RunFiles& /*files*/) override {
    last_mmHg_ = ankle_mmHg(scenario, m);
    last_step_ = m.step;
  }
  std::vector<TextTable> summary_tables(const Scenario& /*scenario*/,
                                        const std::vector<StepMeasurement>& steps) const override {
    if (steps.empty() || last_step_ != steps.back().step) return {};
    const double p = last_mmHg_;
    TextTable table(
        "Compression class (RAL-GZ 387: the mean pressure at B; I 18-21, II 23-32, "
        "III 34-46, IV >= 49 mmHg), load step " +
            std::to_string(steps.back().step),
        {"region", "p_mean [mmHg]", "class"});
    table.add_row({ankle_.name, format_fixed(p, 2),
                   std::isnan(p) ? "no contact in the region" : ral_gz_387_class(p).text});
    return {table};
  }

 private:
  double ankle_mmHg(const Scenario& scenario, const StepMeasurement& m) const {
    const RegionPressure r =
        region_pressure(ankle_, scenario.mesh.triangles, m.state.positions_m, m.field);
    if (r.n_contact_vertices == 0) return std::numeric_limits<double>::quiet_NaN();
    return units::to_mmHg(r.mean_Pa);
  }

  BodyRegion ankle_;
  double last_mmHg_ = std::numeric_limits<double>::quiet_NaN();
  int last_step_ = -1;
};

}  // namespace

PartEntry<MeasurementMaker> compression_class_measurement_entry() {
  PartEntry<MeasurementMaker> e;
  e.name = "compression class";
  e.subsection = "Compression class";
  e.description =
      "the RAL-GZ 387 compression class the mean pressure in the ankle region (B) meets: "
      "columns ankle_p_mean_mmHg and compression_class (1-4; 1.5, 2.5, 3.5 between two "
      "classes; 0 below class I) and a line on screen.";
  e.declare_parameters = [](ParameterTree& prm) {
    prm.declare_text("Region", "B",
                     "The region of Measurements/Regions/Definitions at the ankle's measuring "
                     "point B (its smallest girth), whose mean pressure sets the class.");
  };
  e.parse = [](ParameterTree& prm) -> MeasurementMaker {
    const std::string name = prm.get("Region");
    // The region is defined in the sibling subsection Regions.
    prm.leave_subsection();
    std::vector<BodyRegion> regions;
    try {
      Subsection in(prm, "Regions");
      regions = parse_body_regions(prm.get("Definitions"));
    } catch (const std::invalid_argument& error) {
      prm.enter_subsection("Compression class");
      throw std::invalid_argument("Region '" + name +
                                  "': Measurements/Regions/Definitions: " + error.what());
    }
    prm.enter_subsection("Compression class");
    for (const BodyRegion& region : regions)
      if (region.name == name)
        return [region] { return std::make_unique<CompressionClassMeasurement>(region); };
    std::vector<std::string> names;
    for (const BodyRegion& region : regions) names.push_back(region.name);
    throw std::invalid_argument("Region: no region '" + name +
                                "' in Measurements/Regions/Definitions" +
                                did_you_mean(name, names));
  };
  return e;
}

}  // namespace tightfit
