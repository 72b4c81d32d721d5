// Measurements/List: air-pack sensors. sensors.csv: at every load step, each virtual air-pack
// sensor's reading (instruments/disc_sensor.h) beside what the instrument of the paper's
// Table 1 would display (its range and accuracy), and the step's mean contact pressure.
// Sensors are declared by coordinates (projected onto the body at every step) or, on a
// cylinder, as the paper's 11 points (instruments/paper_cross.h) on top of it.
#include "cases/csv_measurement.h"
#include "cases/parts/cylinder_body.h"
#include "cases/parts/part_entries.h"
#include "cases/step_measurement.h"
#include "core/units.h"
#include "instruments/disc_sensor.h"
#include "instruments/paper_cross.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace tightfit {

namespace {

struct SensorPlacement {
  std::string name;
  Vec3 point_m = Vec3::Zero();  // coordinates: projected onto the body at every step
  // A paper-cross point on a cylinder: the offsets from the crossing on top.
  bool on_cylinder_cross = false;
  CrossPoint cross;
};

class AirPackSensors final : public CsvMeasurement {
 public:
  AirPackSensors(std::vector<SensorPlacement> sensors, AirPackSpecification specification)
      : CsvMeasurement("sensors.csv", {"step", "alpha", "sensor", "x_m", "y_m", "z_m",
                                       "p_sensor_Pa", "p_sensor_gf_cm2", "displayed_gf_cm2",
                                       "accuracy_gf_cm2", "range_max_gf_cm2", "in_range", "force_N",
                                       "covered_area_m2", "n_triangles", "p_mean_Pa"}),
        sensors_(std::move(sensors)),
        specification_(specification) {}

 protected:
  std::vector<std::vector<CsvCell>> rows(const Scenario& scenario,
                                         const StepMeasurement& m) override {
    std::vector<std::vector<CsvCell>> table;
    for (const SensorPlacement& sensor : sensors_) {
      const SurfacePoint at = scenario.body->body().query(centre_of(sensor, scenario));
      const DiscReading r =
          read_disc(m.state.positions_m, scenario.mesh.triangles, m.field.pressure_Pa,
                    at.closest_point_m, at.outward_normal, specification_);
      const Vec3& x = at.closest_point_m;
      table.push_back({m.step, m.alpha, sensor.name, x.x(), x.y(), x.z(), r.pressure_Pa,
                       units::to_gf_per_cm2(r.pressure_Pa), units::to_gf_per_cm2(r.displayed_Pa),
                       units::to_gf_per_cm2(specification_.accuracy_Pa),
                       units::to_gf_per_cm2(specification_.range_max_Pa), r.in_range ? 1 : 0,
                       r.force_N, r.covered_area_m2, r.n_triangles, m.p_mean_Pa()});
    }
    return table;
  }

 private:
  // A point near the sensor's place on the body as it is now.
  static Vec3 centre_of(const SensorPlacement& sensor, const Scenario& scenario) {
    if (!sensor.on_cylinder_cross) return sensor.point_m;
    const Cylinder& cylinder =
        cylinder_body_of(*scenario.body, "Measurements/Air-pack sensors/Points = paper cross")
            .cylinder();
    // The crossing lies on top (towards Protocol/Up) at the axis point; arcs are measured at
    // the body's reference radius R0, so the angles stay put as the cylinder grows.
    const double R0 =
        cylinder_body_of(*scenario.body, "Measurements/Air-pack sensors").reference_radius_m();
    const double top_deg =
        cylinder.angle_deg(cylinder.point_on_axis_m() + scenario.parameters.protocol.up);
    SurfaceLocation location;
    location.coordinates =
        Vec3(sensor.cross.axial_m, top_deg * M_PI / 180.0 + sensor.cross.hoop_m / R0, 0.0);
    return cylinder.surface_point_m(location);
  }

  std::vector<SensorPlacement> sensors_;
  AirPackSpecification specification_;
};

// "paper cross", or points "x,y,z; x,y,z; ..." (m).
std::vector<SensorPlacement> parse_points(const std::string& text) {
  std::vector<SensorPlacement> sensors;
  if (text == "paper cross") {
    for (const CrossPoint& p : paper_cross_points()) {
      SensorPlacement s;
      s.name = p.name;
      s.on_cylinder_cross = true;
      s.cross = p;
      sensors.push_back(s);
    }
    return sensors;
  }
  std::stringstream list(text);
  for (std::string piece; std::getline(list, piece, ';');) {
    if (piece.find_first_not_of(" \t") == std::string::npos) continue;
    std::stringstream numbers(piece);
    SensorPlacement s;
    char comma1 = 0, comma2 = 0;
    numbers >> s.point_m.x() >> comma1 >> s.point_m.y() >> comma2 >> s.point_m.z();
    std::string rest;
    numbers >> rest;
    if (!numbers.eof() || numbers.bad() || comma1 != ',' || comma2 != ',' || !rest.empty() ||
        !s.point_m.allFinite())
      throw std::invalid_argument("Points: cannot read '" + piece +
                                  "' as x,y,z (m); expected 'paper cross' or x,y,z; x,y,z; ...");
    s.name = "S" + std::to_string(sensors.size() + 1);
    sensors.push_back(s);
  }
  if (sensors.empty()) throw std::invalid_argument("Points: no sensor given");
  return sensors;
}

}  // namespace

PartEntry<MeasurementMaker> air_pack_sensors_measurement_entry() {
  PartEntry<MeasurementMaker> e;
  e.name = "air-pack sensors";
  e.subsection = "Air-pack sensors";
  e.description =
      "sensors.csv: virtual air-pack sensors (discs on the body reading the contact force "
      "through them over their area) beside the displayed value of the paper's instrument.";
  e.declare_parameters = [](ParameterTree& prm) {
    const AirPackSpecification table1;
    prm.declare_text("Points", "paper cross",
                     "Where the sensors sit on the body: 'paper cross' (a cylinder body: the "
                     "paper's 11 points on two crossing lines on top, docs/instruments.md) or "
                     "points x,y,z separated by ';' (m), each moved to the closest point of the "
                     "body at every load step.");
    prm.declare_double("Diameter", table1.diameter_m, 1e-5, ParameterTree::unbounded,
                       "Diameter of the air pack (m). Table 1: 15 mm.");
    prm.declare_double("Range maximum", table1.range_max_Pa, 0, ParameterTree::unbounded,
                       "Largest pressure the instrument displays (Pa). Table 1: 70 gf/cm^2 = "
                       "6864.655 Pa.");
    prm.declare_double("Accuracy", table1.accuracy_Pa, 0, ParameterTree::unbounded,
                       "The instrument's accuracy, +/- (Pa). Table 1: 1.5 gf/cm^2 = 147.1 Pa.");
  };
  e.parse = [](ParameterTree& prm) -> MeasurementMaker {
    const std::vector<SensorPlacement> sensors = parse_points(prm.get("Points"));
    AirPackSpecification specification;
    specification.diameter_m = prm.get_double("Diameter");
    specification.range_max_Pa = prm.get_double("Range maximum");
    specification.accuracy_Pa = prm.get_double("Accuracy");
    return [=] { return std::make_unique<AirPackSensors>(sensors, specification); };
  };
  return e;
}

}  // namespace tightfit
