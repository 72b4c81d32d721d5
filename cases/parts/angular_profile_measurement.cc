// Measurements/List: angular profile. pressure_theta.csv: the mean pressure of the contact
// vertices in equal sectors round the cylinder's axis at the last load step (the paper's
// Figures 11 and 13), beside the step's closed form.
#include "cases/parts/cylinder_body.h"
#include "cases/parts/part_entries.h"
#include "cases/step_measurement.h"
#include "io/csv_table.h"

namespace tightfit {

namespace {

class AngularProfileMeasurement final : public Measurement {
 public:
  explicit AngularProfileMeasurement(int n_bins) : n_bins_(n_bins) {}

  void after_run(const Scenario& scenario, const std::vector<StepMeasurement>& steps,
                 const RunFiles& files) override {
    if (!files.write_tables || steps.empty()) return;
    const StepMeasurement& m = steps.back();
    const CylinderBody& body = cylinder_body_of(*scenario.body, "Measurements: angular profile");
    const AngularProfile profile =
        pressure_against_angle(m.field, m.state.positions_m, body.cylinder(), n_bins_);
    CsvTable table(files.path("pressure_theta.csv"),
                   {"theta_deg", "pressure_Pa", "n_vertices", "p_theory_Pa", "alpha"});
    for (std::size_t b = 0; b < profile.theta_deg.size(); ++b)
      table.write_row({profile.theta_deg[b], profile.pressure_Pa[b], profile.n_vertices[b],
                       m.p_theory_Pa, m.alpha});
  }
  std::vector<std::string> file_names() const override { return {"pressure_theta.csv"}; }

 private:
  int n_bins_;
};

}  // namespace

PartEntry<MeasurementMaker> angular_profile_measurement_entry() {
  PartEntry<MeasurementMaker> e;
  e.name = "angular profile";
  e.subsection = "Angular profile";
  e.description =
      "pressure_theta.csv: pressure against the angle round a cylinder body, last step.";
  e.declare_parameters = [](ParameterTree& prm) {
    prm.declare_integer("Angle bins", 36, 1, 3600,
                        "Sectors round the cylinder for pressure_theta.csv (-).");
  };
  e.parse = [](ParameterTree& prm) -> MeasurementMaker {
    const int n_bins = prm.get_integer("Angle bins");
    return [n_bins] { return std::make_unique<AngularProfileMeasurement>(n_bins); };
  };
  return e;
}

}  // namespace tightfit
