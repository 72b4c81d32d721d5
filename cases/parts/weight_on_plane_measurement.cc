// Measurements/List: weight on plane. A garment lying flat and unstretched on a plane body
// under gravity (docs/model.md, "Closed forms"): the plane carries the weight of each
// piece of cloth where it lies, so the contact traction is the weight per area,
// p = rho_A g (up . n), at every vertex; the garment's own forces vanish, so the paper's
// definition reads zero. The reference pressure (p_theory_Pa) is the former under the contact
// traction, the latter under the garment force, and zero while gravity is off.
#include "cases/parts/part_entries.h"
#include "cases/step_measurement.h"

namespace tightfit {

namespace {

class WeightOnPlane final : public Measurement {
 public:
  std::optional<double> reference_pressure_Pa(const Scenario& scenario,
                                              const StepMeasurement& m) const override {
    return weight_per_area_Pa(scenario, m);
  }
  std::vector<std::string> columns() const override { return {"weight_per_area_Pa"}; }
  std::vector<double> values(const Scenario& scenario, const StepMeasurement& m) const override {
    return {weight_per_area_Pa(scenario, m)};
  }

 private:
  static double weight_per_area_Pa(const Scenario& scenario, const StepMeasurement& m) {
    const CaseParameters& c = scenario.parameters;
    const bool gravity_on =
        m.step == 0 ? c.protocol.gravity_while_settling : c.protocol.gravity_while_measuring;
    if (!gravity_on || c.pressure.definition != PressureDefinition::contact_traction) return 0.0;
    const Vec3 normal = scenario.body->body().query(Vec3::Zero()).outward_normal;
    return -c.fabric.areal_density_kg_per_m2 * scenario.problem.gravity_m_per_s2.dot(normal);
  }
};

}  // namespace

PartEntry<MeasurementMaker> weight_on_plane_measurement_entry() {
  PartEntry<MeasurementMaker> e;
  e.name = "weight on plane";
  e.subsection = "Weight on plane";
  e.description =
      "the closed form of an unstretched garment lying on a plane body: p_theory_Pa = rho_A g "
      "(up . n) under the contact traction, 0 under the garment force; column "
      "weight_per_area_Pa.";
  e.parse = [](ParameterTree&) -> MeasurementMaker {
    return [] { return std::make_unique<WeightOnPlane>(); };
  };
  return e;
}

}  // namespace tightfit
