// Measurements/List: stamps. stamps.csv: at every load step, each virtual stamp
// (instruments/stamp.h) with its fitted principal stretches, the principal tensions the law
// gives there, the body's radii of curvature along them and the paper's Eq. 3
// (instruments/eq3_pressure.h) beside the simulated contact pressure at the stamp's centre.
#include "cases/csv_measurement.h"
#include "cases/parts/part_entries.h"
#include "cases/step_measurement.h"
#include "instruments/eq3_pressure.h"
#include "instruments/paper_cross.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace tightfit {

namespace {

// Where the stamps are printed, resolved on the scenario's mesh at the first step.
struct StampLayout {
  bool paper_cross = false;  // on panel 0, crossing at its centre
  std::vector<StampDefinition> stamps;
  double radius_m = 0.02;
  int n_outline_points = 360;
};

double radius_of_curvature_m(double curvature_per_m) {
  return std::abs(curvature_per_m) > 1e-12 ? 1.0 / curvature_per_m
                                           : std::numeric_limits<double>::infinity();
}

class Stamps final : public CsvMeasurement {
 public:
  explicit Stamps(StampLayout layout)
      : CsvMeasurement("stamps.csv", {"step", "alpha", "stamp", "panel", "u_m", "v_m", "x_m", "y_m",
                                      "z_m", "stretch_max", "stretch_min", "grain_angle_max_deg",
                                      "tension_max_N_per_m", "tension_min_N_per_m", "radius_max_m",
                                      "radius_min_m", "p_eq3_Pa", "p_sim_Pa", "rel_difference"}),
        layout_(std::move(layout)) {}

 protected:
  std::vector<std::vector<CsvCell>> rows(const Scenario& scenario,
                                         const StepMeasurement& m) override {
    if (printed_.empty()) print(scenario.mesh);
    std::vector<std::vector<CsvCell>> table;
    const RigidBody& body = scenario.body->body();
    for (const PrintedStamp& stamp : printed_) {
      const StampFit fit = fit_stamp(scenario.mesh, m.state.positions_m, stamp, body);
      const Eq3Estimate eq3 = eq3_pressure(fit, *scenario.law, body);
      const double p_sim = interpolate(scenario.mesh, m.field.pressure_Pa, stamp.centre);
      const StampDefinition& d = stamp.definition;
      table.push_back({m.step, m.alpha, d.name, d.panel, d.centre_m.x(), d.centre_m.y(),
                       fit.centre_m.x(), fit.centre_m.y(), fit.centre_m.z(), fit.stretch_max,
                       fit.stretch_min, fit.grain_angle_max_deg, eq3.tension_max_N_per_m,
                       eq3.tension_min_N_per_m, radius_of_curvature_m(eq3.curvature_max_per_m),
                       radius_of_curvature_m(eq3.curvature_min_per_m), eq3.pressure_Pa, p_sim,
                       p_sim != 0.0 ? (eq3.pressure_Pa - p_sim) / p_sim
                                    : std::numeric_limits<double>::quiet_NaN()});
    }
    return table;
  }

 private:
  void print(const SimulationMesh& mesh) {
    std::vector<StampDefinition> stamps = layout_.stamps;
    if (layout_.paper_cross) {
      const auto [low, high] = panel_extent_m(mesh, 0);
      const Vec2 crossing = 0.5 * (low + high);
      for (const CrossPoint& p : paper_cross_points())
        stamps.push_back({p.name, 0, crossing + Vec2(p.hoop_m, p.axial_m), layout_.radius_m});
    }
    try {
      for (const StampDefinition& s : stamps)
        printed_.push_back(print_stamp(mesh, s, layout_.n_outline_points));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("Measurements/Stamps/Centres: ") + e.what());
    }
  }

  StampLayout layout_;
  std::vector<PrintedStamp> printed_;
};

// "paper cross", or "panel:u,v; ..." (u along the weft, v along the warp, m).
StampLayout parse_layout(const std::string& text, double radius_m) {
  StampLayout layout;
  layout.radius_m = radius_m;
  if (text == "paper cross") {
    layout.paper_cross = true;
    return layout;
  }
  std::stringstream list(text);
  for (std::string piece; std::getline(list, piece, ';');) {
    if (piece.find_first_not_of(" \t") == std::string::npos) continue;
    std::stringstream in(piece);
    StampDefinition s;
    char colon = 0, comma = 0;
    in >> s.panel >> colon >> s.centre_m.x() >> comma >> s.centre_m.y();
    std::string rest;
    in >> rest;
    if (in.bad() || colon != ':' || comma != ',' || !rest.empty() || s.panel < 0 ||
        !s.centre_m.allFinite())
      throw std::invalid_argument("Centres: cannot read '" + piece +
                                  "' as panel:u,v (u, v in m); expected 'paper cross' or "
                                  "panel:u,v; panel:u,v; ...");
    s.name = "S" + std::to_string(layout.stamps.size() + 1);
    s.radius_m = radius_m;
    layout.stamps.push_back(s);
  }
  if (layout.stamps.empty()) throw std::invalid_argument("Centres: no stamp given");
  return layout;
}

}  // namespace

PartEntry<MeasurementMaker> stamps_measurement_entry() {
  PartEntry<MeasurementMaker> e;
  e.name = "stamps";
  e.subsection = "Stamps";
  e.description =
      "stamps.csv: circles printed on the garment in pattern space, their fitted principal "
      "stretches and the paper's Eq. 3 beside the simulated pressure at each centre.";
  e.declare_parameters = [](ParameterTree& prm) {
    prm.declare_text("Centres", "paper cross",
                     "Where the stamps are printed: 'paper cross' (the paper's 11 stamps on two "
                     "crossing lines through the centre of panel 0, docs/instruments.md) or "
                     "panel:u,v separated by ';', u along the weft and v along the warp from "
                     "the panel's lower-left corner (m).");
    prm.declare_double("Radius", 0.02, 1e-4, ParameterTree::unbounded,
                       "Radius of every stamp in pattern space (m). The paper: 2 cm.");
    prm.declare_integer("Outline points", 360, 8, 100000,
                        "Points round each stamp's outline used by the fit (-).");
  };
  e.parse = [](ParameterTree& prm) -> MeasurementMaker {
    StampLayout layout = parse_layout(prm.get("Centres"), prm.get_double("Radius"));
    layout.n_outline_points = prm.get_integer("Outline points");
    return [=] { return std::make_unique<Stamps>(layout); };
  };
  return e;
}

}  // namespace tightfit
