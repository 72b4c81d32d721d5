// Measurements/List: pictures. pressure_front.png and pressure_back.png: the pressure map of the
// last load step seen from the front and from the back (orthographic views along View direction
// and against it), on the body's surface (cases/body_surface_pressure.h) or on the garment,
// framed round the garment with its edge drawn, with a colour bar in kPa and mmHg that marks
// pressures above its top (io/pressure_picture.h); with Every step, also one pair
// per load step, pressure_front_NNNN.png and pressure_back_NNNN.png; with Panels at alpha,
// pressure_steps.png, chosen load steps side by side.
#include "cases/body_surface_pressure.h"
#include "cases/parts/part_entries.h"
#include "cases/step_measurement.h"
#include "core/number_text.h"
#include "io/pressure_picture.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace tightfit {

namespace {

struct PictureSettings {
  PictureView front;
  bool on_body = true;
  bool every_step = false;
  std::vector<double> panel_alphas;  // pressure_steps.png: the steps nearest these alphas
  PictureStyle style;
};

class PicturesMeasurement final : public Measurement {
 public:
  explicit PicturesMeasurement(PictureSettings settings) : settings_(std::move(settings)) {}

  void after_step(const Scenario& scenario, const StepMeasurement& m,
                  const RunFiles& files) override {
    if (!files.write_tables) return;
    // The steps' arrays are released once written: a panel's surface is copied now.
    if (is_panel_step(scenario, m.step)) {
      panels_.push_back(surface_of(scenario, m));
      char caption[96];
      std::snprintf(caption, sizeof caption, "alpha %.3g, mean %.0f Pa", m.alpha, m.p_mean_Pa());
      captions_.emplace_back(caption);
    }
    if (!settings_.every_step) return;
    char suffix[32];
    std::snprintf(suffix, sizeof suffix, "_%04d", m.step);
    draw(scenario, m, files, suffix);
  }
  void after_run(const Scenario& scenario, const std::vector<StepMeasurement>& steps,
                 const RunFiles& files) override {
    if (!steps.empty() && files.write_tables) draw(scenario, steps.back(), files, "");
    if (!panels_.empty() && files.write_tables) {
      PictureStyle style = settings_.style;
      style.width = std::max(style.width, 260 * static_cast<int>(panels_.size()) + 260);
      style.title = scenario.parameters.garment.name + ": " +
                    (settings_.on_body ? "on the body" : "the garment") + " at " +
                    std::to_string(panels_.size()) + " load steps";
      write_pressure_panels(files.path("pressure_steps.png"), panels_, captions_, settings_.front,
                            style);
    }
  }
  std::vector<std::string> file_names() const override {
    std::vector<std::string> names{"pressure_front.png", "pressure_back.png"};
    if (!settings_.panel_alphas.empty()) names.emplace_back("pressure_steps.png");
    return names;
  }

 private:
  // The step nearest one of the panel alphas (each alpha its nearest step).
  bool is_panel_step(const Scenario& scenario, int step) const {
    for (double alpha : settings_.panel_alphas) {
      int nearest = 0;
      for (std::size_t k = 0; k < scenario.alphas.size(); ++k)
        if (std::abs(scenario.alphas[k] - alpha) < std::abs(scenario.alphas[nearest] - alpha))
          nearest = static_cast<int>(k);
      if (nearest == step) return true;
    }
    return false;
  }

  PressureSurface surface_of(const Scenario& scenario, const StepMeasurement& m) const {
    PressureSurface surface;
    if (settings_.on_body) {
      BodySurfacePressure body = body_surface_pressure(scenario, m);
      surface.points_m = std::move(body.surface.vertices_m);
      surface.triangles = std::move(body.surface.triangles);
      surface.pressure_Pa = std::move(body.pressure_Pa);
      surface.has_pressure = std::move(body.under_garment);
      // Framed round the garment, its edge drawn over the body where no more than two of its
      // edges lie in front of it (the garment lies on the body).
      surface.frame_m = m.state.positions_m;
      surface.outline_depth_tolerance_m = 2 * scenario.mean_edge_length_m;
    } else {
      surface.points_m = m.state.positions_m;
      surface.triangles = scenario.mesh.triangles;
      surface.pressure_Pa = m.field.pressure_Pa;
      surface.has_pressure = m.field.contact;
      surface.grey_means = "not in contact";
      surface.outline_depth_tolerance_m = scenario.mean_edge_length_m;
    }
    surface.outline_m = boundary_segments(m.state.positions_m, scenario.mesh.triangles);
    return surface;
  }

  void draw(const Scenario& scenario, const StepMeasurement& m, const RunFiles& files,
            const std::string& suffix) const {
    const PressureSurface surface = surface_of(scenario, m);
    const PictureView back{-settings_.front.direction, settings_.front.up};
    for (const auto& [side, view] : {std::pair<const char*, PictureView>{"front", settings_.front},
                                     std::pair<const char*, PictureView>{"back", back}}) {
      PictureStyle style = settings_.style;
      char title[256];
      std::snprintf(title, sizeof title, "%s, %s: %s view, load step %d (alpha %.3g)",
                    scenario.parameters.garment.name.c_str(),
                    settings_.on_body ? scenario.body->body().name().c_str() : "garment", side,
                    m.step, m.alpha);
      style.title = title;
      write_pressure_picture(files.path(std::string("pressure_") + side + suffix + ".png"), surface,
                             view, style);
    }
  }

  PictureSettings settings_;
  std::vector<PressureSurface> panels_;
  std::vector<std::string> captions_;
};

}  // namespace

PartEntry<MeasurementMaker> pictures_measurement_entry() {
  PartEntry<MeasurementMaker> e;
  e.name = "pictures";
  e.subsection = "Pictures";
  e.description =
      "pressure_front.png, pressure_back.png: the pressure map of the last step from the front "
      "and the back, coloured, with a colour bar in kPa and mmHg.";
  e.declare_parameters = [](ParameterTree& prm) {
    prm.declare_vector("View direction", "0,1,0",
                       "The front picture looks along this direction, the back one against it "
                       "(orthographic views; -). The default looks at a body that stands along "
                       "+z and faces -y, as mesh bodies are imported (docs/bodies.md).");
    prm.declare_vector("Up", "0,0,1", "The direction shown upwards in both pictures (-).");
    prm.declare_selection("Surface", "body", "body|garment",
                          "Draw the pressure on the body's surface (mapped from the garment, "
                          "grey where no garment lies) or on the garment itself.");
    prm.declare_bool("Every step", false,
                     "Also draw pressure_front_NNNN.png and pressure_back_NNNN.png at every load "
                     "step.");
    prm.declare_text("Panels at alpha", "",
                     "Also draw pressure_steps.png: the load steps nearest these alphas "
                     "(comma-separated, -) side by side on one scale and one colour bar, as the "
                     "paper's Figure 6. Empty: none.");
    prm.declare_integer("Width", 800, 320, 8000, "Picture width (pixels).");
    prm.declare_integer("Height", 600, 200, 8000, "Picture height (pixels).");
    prm.declare_double("Top pressure", 0, 0, ParameterTree::unbounded,
                       "Pressure at the top of the colour bar, Pa; 0: the largest one drawn.");
  };
  e.parse = [](ParameterTree& prm) -> MeasurementMaker {
    PictureSettings s;
    s.front.direction = prm.get_vector("View direction");
    s.front.up = prm.get_vector("Up");
    if (!(s.front.direction.norm() > 0))
      throw std::invalid_argument("View direction: the direction is zero");
    if (!(s.front.up.cross(s.front.direction).norm() >
          1e-9 * s.front.up.norm() * s.front.direction.norm()))
      throw std::invalid_argument("Up: zero or along View direction");
    s.on_body = prm.get("Surface") == "body";
    s.every_step = prm.get_bool("Every step");
    for (const std::string& word : prm.get_list("Panels at alpha")) {
      const std::optional<double> alpha = whole_number(word);
      if (!alpha || !(*alpha > 0))
        throw std::invalid_argument("Panels at alpha: '" + word + "' is not a positive number");
      s.panel_alphas.push_back(*alpha);
    }
    s.style.width = prm.get_integer("Width");
    s.style.height = prm.get_integer("Height");
    s.style.top_pressure_Pa = prm.get_double("Top pressure");
    return [s] { return std::make_unique<PicturesMeasurement>(s); };
  };
  return e;
}

}  // namespace tightfit
