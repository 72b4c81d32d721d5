// Placement/Kind = dressing: the garment's panels, unsewn, wrapped on an elliptic cylinder round
// an axis outside the body (contact/panel_wrap.h), then sewn onto the body by the dressing stage
// (massspring/dressing.h): seam springs close the seams while the body grows from a shrunk
// start to its shape; the welded garment is the start of the load steps, on either backend
// (docs/dressing.md).
#include "cases/parts/part_entries.h"
#include "cases/scenario.h"
#include "contact/panel_wrap.h"
#include "contact/surface_return.h"
#include "core/mesh_transfer.h"
#include "massspring/dressing.h"
#include "massspring/massspring_backend.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace tightfit {

namespace {

// "front: 0, back: 180" -> degrees by panel name.
std::map<std::string, double> parse_angles(const std::vector<std::string>& words) {
  std::map<std::string, double> angles;
  for (const std::string& word : words) {
    const auto colon = word.rfind(':');
    if (colon == std::string::npos)
      throw std::invalid_argument("Panel angles: '" + word + "' is not PANEL:DEGREES");
    std::string name = word.substr(0, colon);
    while (!name.empty() && name.back() == ' ') name.pop_back();
    try {
      std::size_t used = 0;
      const std::string number = word.substr(colon + 1);
      angles[name] = std::stod(number, &used);
      if (number.find_first_not_of(' ', used) != std::string::npos) throw std::invalid_argument("");
    } catch (const std::exception&) {
      throw std::invalid_argument("Panel angles: '" + word + "' has no angle in degrees");
    }
  }
  return angles;
}

// Coarse to fine (Coarse edge length): the case's garment meshed at `coarse_m` is dressed by
// `dress_coarse` in a scenario of its own; with a settle rule (a relative tolerance > 0) the
// welded coarse garment then settles as the case's first load step would (gravity, friction),
// on the mass-spring backend with its default settings, the rms stop rule at that relative
// tolerance and the rule's net force tolerance and slide damping, so that the slow slide of a
// dressed top over the body is done on the cheap mesh;
// its state is carried to the case's mesh in pattern space (core/mesh_transfer.h). Fine vertices on
// a coarse triangle's chord of the body may lie inside it by the chord's sagitta (h^2 / 8 R: about
// 2 mm for 30 mm edges round a 5 cm arm); up to a quarter of a coarse edge they go back onto the
// surface, as a dressing's own welded vertices do.
struct CoarseSettle {
  double relative_tolerance = 0.0;   // 0: the coarse garment is carried as dressed
  double net_force_tolerance = 0.0;  // Mass spring/Net force tolerance of the settle
  double slide_damping_per_s = 0.0;  // Mass spring/Slide damping of the settle
};

std::vector<Vec3> dressed_from_coarse(const Scenario& scenario, double coarse_m,
                                      const CoarseSettle& settle_rule,
                                      const PlacementMaker& dress_coarse) {
  if (scenario.parameters.garment.kind != "pattern file")
    throw std::invalid_argument(
        "Placement/Dressing/Coarse edge length: only a garment cut from a pattern "
        "(Garment/Kind = pattern file) is meshed at another edge length, not Garment/Kind = " +
        scenario.parameters.garment.kind);
  CaseParameters coarse = scenario.parameters;
  coarse.garment.spacing.pattern_edge_length_m = coarse_m;
  coarse.placement.place = dress_coarse;
  std::unique_ptr<Scenario> dressed;
  try {
    dressed = make_scenario(coarse);
  } catch (const SolverError& error) {
    std::ostringstream message;
    message << "on the coarse mesh (Placement/Dressing/Coarse edge length " << coarse_m
            << " m): " << error.what();
    throw SolverError(error.reason(), message.str());
  }
  std::vector<Vec3> coarse_x = dressed->start_positions_m;
  if (settle_rule.relative_tolerance > 0) {
    MassSpringParameters settle;
    settle.stop.norm = StopNorm::rms;
    settle.stop.relative_tolerance = settle_rule.relative_tolerance;
    settle.net_force_tolerance = settle_rule.net_force_tolerance;
    settle.slide_damping_per_s = settle_rule.slide_damping_per_s;
    settle.contact_updates = 0;
    MassSpringBackend backend(dressed->problem, settle);
    backend.set_positions(coarse_x);
    const StepReport report = backend.solve(dressed->prepare_step(0));
    std::printf("  dressing: the coarse mesh settled: %s\n", report.text().c_str());
    coarse_x = backend.state().positions_m;
  }
  std::vector<Vec3> x = transfer_positions(dressed->mesh, coarse_x, scenario.mesh);
  const double allowed_m = 0.25 * dressed->mean_edge_length_m;
  const SurfaceReturn back = return_onto_surface(*scenario.problem.body, x, allowed_m);
  if (back.deepest_m > allowed_m) {
    std::ostringstream message;
    message << "dressing: carried from the coarse mesh, vertex " << back.deepest_point << " lies "
            << back.deepest_m << " m inside the body (more than a quarter of a coarse edge, "
            << allowed_m << " m); dress on a finer coarse mesh (Placement/Dressing/Coarse edge "
            << "length)";
    throw SolverError(StopReason::passed_into_body, message.str());
  }
  std::printf(
      "  dressing: carried from the coarse mesh (%d vertices, mean edge %.3g m) to %d vertices; "
      "%d put back on the body from at most %.3g m inside\n",
      dressed->mesh.n_vertices, dressed->mean_edge_length_m, scenario.mesh.n_vertices,
      back.points_moved, back.deepest_m);
  std::fflush(stdout);
  return x;
}

}  // namespace

void declare_dressing_frames(ParameterTree& prm) {
  prm.declare_integer("Growth frames", 2000, 0, 100000000,
                      "RK4 frames over which the body grows linearly to its own size.");
  prm.declare_integer("Seam ramp frames", 500, 0, 100000000,
                      "RK4 frames over which the seam springs' stiffness rises linearly from "
                      "zero to full.");
  prm.declare_integer("Maximum frames", 40000, 1, 100000000,
                      "Frames the seams have to close in; beyond them the dressing fails "
                      "naming the seam with the widest gap.");
}

void read_dressing_frames(ParameterTree& prm, DressingSettings& settings) {
  settings.growth_frames = prm.get_integer("Growth frames");
  settings.seam_ramp_frames = prm.get_integer("Seam ramp frames");
  settings.maximum_frames = prm.get_integer("Maximum frames");
}

PartEntry<PlacementMaker> dressing_placement_entry() {
  PartEntry<PlacementMaker> e;
  e.name = "dressing";
  e.subsection = "Dressing";
  e.description =
      "the panels unsewn on an elliptic cylinder round an axis, sewn onto the body by seam "
      "springs while the body grows from a shrunk start (docs/dressing.md).";
  e.declare_parameters = [](ParameterTree& prm) {
    prm.declare_vector("Centre", "0,0,0",
                       "A point on the axis, and the point the body is scaled about (m).");
    prm.declare_vector("Axis", "0,0,1", "Direction of the axis the panels are wrapped round (-).");
    prm.declare_vector("Front", "0,-1,0",
                       "The body's front, the direction of angle 0 round the axis (-); angles "
                       "grow towards Axis x Front (the body's left for z up and front -y).");
    prm.declare_double("Semi-axis side", 0.15, 0, ParameterTree::unbounded,
                       "Semi-axis of the elliptic cylinder along Axis x Front (m).");
    prm.declare_double("Semi-axis front", 0.15, 0, ParameterTree::unbounded,
                       "Semi-axis of the elliptic cylinder along Front (m).");
    prm.declare_double("Hem height", 0, -ParameterTree::unbounded, ParameterTree::unbounded,
                       "Where each panel's lowest point goes along the axis from Centre (m); "
                       "pattern y runs up the axis from there.");
    prm.declare_text("Panel angles", "",
                     "Where each panel's middle goes round the axis: 'PANEL:DEGREES, ...' from "
                     "Front; empty: panel k of n at 360 k / n degrees.");
    prm.declare_selection("Scale about", "axis", "point|axis",
                          "The body shrinks about the Axis through Centre (heights kept) or "
                          "about the point Centre.");
    prm.declare_double("Start scale", 0.7, 0.05, 1,
                       "The body's scale about Centre or the axis at the start of the dressing "
                       "(-).");
    declare_dressing_frames(prm);
    prm.declare_double("Seam stiffness factor", 20, 0, ParameterTree::unbounded,
                       "Each zero-rest-length seam spring's stiffness over the law's stiffness "
                       "scale (-).");
    prm.declare_double("Closed gap", 0.05, 0, ParameterTree::unbounded,
                       "The seams are closed when every seam vertex pair is closer than this "
                       "fraction of the mean rest edge length (-); they are then welded.");
    prm.declare_double("Coarse edge length", 0, 0, ParameterTree::unbounded,
                       "Above 0: dress the garment meshed at this edge length (m) instead, and "
                       "carry its welded state to the case's mesh in pattern space (a pattern "
                       "file's garment); 0: dress the case's mesh itself.");
    prm.declare_double("Coarse settle tolerance", 0, 0, ParameterTree::unbounded,
                       "With a Coarse edge length: above 0, the dressed coarse garment first "
                       "settles as the first load step would (gravity, friction), on the "
                       "mass-spring backend with the rms stop rule at this relative tolerance "
                       "(Solver/Relative tolerance); 0: carried as dressed.");
    prm.declare_double("Coarse net force tolerance", 0, 0, ParameterTree::unbounded,
                       "With a Coarse settle tolerance: above 0, the coarse settle also asks the "
                       "net force on the garment below this times its weight (Mass spring/Net "
                       "force tolerance); 0: not asked.");
    prm.declare_double("Coarse slide damping", 0, 0, ParameterTree::unbounded,
                       "With a Coarse net force tolerance: above 0, the coarse settle slides at "
                       "this damping until the garment's slide over the body has ended (Mass "
                       "spring/Slide damping), 1/s; 0: off.");
  };
  e.parse = [](ParameterTree& prm) -> PlacementMaker {
    PanelWrap wrap;
    wrap.centre_m = prm.get_vector("Centre");
    wrap.axis = prm.get_vector("Axis");
    wrap.front = prm.get_vector("Front");
    wrap.semi_axis_side_m = prm.get_double("Semi-axis side");
    wrap.semi_axis_front_m = prm.get_double("Semi-axis front");
    wrap.hem_height_m = prm.get_double("Hem height");
    if (!(wrap.semi_axis_side_m > 0 && wrap.semi_axis_front_m > 0))
      throw std::invalid_argument("Semi-axis side and Semi-axis front must be positive (m)");
    if (!(wrap.axis.norm() > 0)) throw std::invalid_argument("Axis must not be zero");
    const std::map<std::string, double> angles_deg = parse_angles(prm.get_list("Panel angles"));
    DressingSettings settings;
    settings.centre_m = wrap.centre_m;
    if (prm.get("Scale about") == "axis") settings.scale_axis = wrap.axis;
    settings.start_scale = prm.get_double("Start scale");
    read_dressing_frames(prm, settings);
    settings.mass_spring.seam_stiffness_factor = prm.get_double("Seam stiffness factor");
    settings.closed_fraction = prm.get_double("Closed gap");
    settings.progress = &std::cout;
    const double coarse_m = prm.get_double("Coarse edge length");
    CoarseSettle settle;
    settle.relative_tolerance = prm.get_double("Coarse settle tolerance");
    settle.net_force_tolerance = prm.get_double("Coarse net force tolerance");
    settle.slide_damping_per_s = prm.get_double("Coarse slide damping");
    if (settle.slide_damping_per_s > 0 && !(settle.net_force_tolerance > 0))
      throw std::invalid_argument(
          "Coarse slide damping needs a Coarse net force tolerance above 0 (the end of the "
          "slide is read on the net force limit)");
    PlacementMaker dress_here = [=](const Scenario& scenario) {
      PanelWrap placed = wrap;
      const std::vector<Panel>& panels = scenario.garment.panels;
      for (std::size_t p = 0; p < panels.size(); ++p) {
        double degrees = 360.0 * double(p) / double(panels.size());
        if (!angles_deg.empty()) {
          const auto found = angles_deg.find(panels[p].name);
          if (found == angles_deg.end())
            throw std::invalid_argument("Placement/Dressing/Panel angles: no angle for panel '" +
                                        panels[p].name + "'");
          degrees = found->second;
        }
        placed.panel_angles_rad.push_back(degrees * M_PI / 180.0);
      }
      for (const auto& [name, degrees] : angles_deg) {
        bool known = false;
        for (const Panel& panel : panels) known = known || panel.name == name;
        if (!known)
          throw std::invalid_argument(
              "Placement/Dressing/Panel angles: the garment has no panel '" + name + "'");
      }
      const std::vector<Vec3> open =
          wrap_panels_round_axis(scenario.garment, scenario.mesh, placed);
      try {
        const DressingResult dressed = dress(scenario.problem, scenario.garment, open, settings);
        std::printf(
            "  dressing: seams closed (largest gap %.3g m < %.3g m) after %d frames, %.1f s; %d "
            "welded vertices put back on the body from at most %.3g m inside\n",
            dressed.largest_seam_gap_m, dressed.closed_below_m, dressed.frames,
            dressed.wall_seconds, dressed.vertices_put_back, dressed.deepest_m);
        std::fflush(stdout);
        return dressed.welded_positions_m;
      } catch (const std::invalid_argument& error) {
        throw std::invalid_argument(std::string("Placement/Dressing: ") + error.what());
      }
    };
    if (!(coarse_m > 0)) return dress_here;
    return [=](const Scenario& scenario) {
      return dressed_from_coarse(scenario, coarse_m, settle, dress_here);
    };
  };
  return e;
}

}  // namespace tightfit
