// Placement/Kind = dressing: the garment's panels, unsewn, wrapped on an elliptic cylinder round
// an axis outside the body (bodies/panel_wrap.h), then sewn onto the body by the dressing stage
// (core/dressing_stage.h): seam springs close the seams while the body grows from a shrunk
// start to its shape; the welded garment is the start of the load steps, on either backend
// (docs/dressing.md).
#include "bodies/panel_wrap.h"
#include "bodies/surface_return.h"
#include "cases/coarse_dressing.h"
#include "cases/dressing_frame.h"
#include "cases/failed_dressing_output.h"
#include "cases/parts/part_entries.h"
#include "cases/scenario.h"
#include "core/backend_registry.h"
#include "core/closest_names.h"
#include "core/mesh_transfer.h"

#include <algorithm>
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
    // The frame (docs/dressing.md, "The frame from the landmarks"): the torso's own by default,
    // numbers for a body without landmarks (a cylinder).
    prm.declare_text("Centre", "torso",
                     "A point on the axis, and the point the body is scaled about: three numbers "
                     "x,y,z (m), 'torso' for the torso axis's point at the crotch, or 'torso at "
                     "LINE' for its point at a line of the torso (crotch, hips, waist, "
                     "under-bust, bust, armpit, neck base), from the body's landmarks.");
    prm.declare_text("Axis", "torso",
                     "Direction of the axis the panels are wrapped round: three numbers x,y,z "
                     "(-), 'torso' for the torso's axis (the line through the centroids of its "
                     "sections, upwards), or 'vertical' for the body's up (z, as Body/Mesh/Up "
                     "axis turned it).");
    prm.declare_text("Front", "torso",
                     "The body's front, the direction of angle 0 round the axis: three numbers "
                     "x,y,z (-), or 'torso' for the torso's front; angles grow towards Axis x "
                     "Front (the body's left for z up and front -y).");
    prm.declare_text("Semi-axis side", "bust + 0.01",
                     "Semi-axis of the elliptic cylinder along Axis x Front: METRES, or 'LINE + "
                     "METRES' with LINE one of hips, waist, under-bust, bust: the torso's "
                     "section at that girth line shrunk to Start scale (its largest distance "
                     "from the axis that way, times Start scale) plus METRES (m).");
    prm.declare_text("Semi-axis front", "bust + 0.01",
                     "Semi-axis of the elliptic cylinder along Front: METRES, or 'LINE + METRES' "
                     "as Semi-axis side, read along Front (m).");
    prm.declare_text("Hem height", "armpit - 0.35",
                     "Where each panel's lowest point goes along the axis from Centre: METRES, or "
                     "'LINE + METRES' / 'LINE - METRES' from a line of the torso (crotch, hips, "
                     "waist, under-bust, bust, armpit: the lower armpit, neck base), its height "
                     "along the axis from Centre plus METRES (m); pattern y runs up the axis from "
                     "there.");
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
    prm.declare_double(
        "Coarse settle tolerance", 0, 0, ParameterTree::unbounded,
        "With a Coarse edge length: above 0, the dressed coarse garment first "
        "settles as the first load step would (gravity, friction), on the "
        "mass-spring backend with its defaults for the body (on a body mesh "
        "with flat faces or friction: the contact damper, time step updates, net "
        "force rule and creep slide) and the rms stop rule at this relative tolerance "
        "(Solver/Relative tolerance); 0: carried as dressed.");
    prm.declare_double("Coarse net force tolerance", 0, 0, ParameterTree::unbounded,
                       "With a Coarse settle tolerance: above 0, the coarse settle also asks the "
                       "net force on the garment below this times its weight (Mass spring/Net "
                       "force tolerance); 0: the backend's default (0.05 on a body mesh with flat "
                       "faces or friction, not asked elsewhere).");
    prm.declare_double("Coarse slide damping", 0, 0, ParameterTree::unbounded,
                       "With a net force rule (Coarse net force tolerance, or a body mesh with "
                       "flat faces or friction): above 0, the coarse settle slides at "
                       "this damping until the garment's slide over the body has ended (Mass "
                       "spring/Slide damping), 1/s; 0: off.");
  };
  e.parse = [](ParameterTree& prm) -> PlacementMaker {
    const DressingFrameSpec frame = parse_dressing_frame(
        prm.get("Centre"), prm.get("Axis"), prm.get("Front"), prm.get("Semi-axis side"),
        prm.get("Semi-axis front"), prm.get("Hem height"));
    const std::map<std::string, double> angles_deg = parse_angles(prm.get_list("Panel angles"));
    DressingSettings settings;
    const bool scale_about_axis = prm.get("Scale about") == "axis";
    settings.start_scale = prm.get_double("Start scale");
    read_dressing_frames(prm, settings);
    settings.seam_stiffness_factor = prm.get_double("Seam stiffness factor");
    settings.closed_fraction = prm.get_double("Closed gap");
    settings.progress = &std::cout;
    const double coarse_m = prm.get_double("Coarse edge length");
    CoarseSettle settle;
    settle.relative_tolerance = prm.get_double("Coarse settle tolerance");
    settle.net_force_tolerance = prm.get_double("Coarse net force tolerance");
    settle.slide_damping_per_s = prm.get_double("Coarse slide damping");
    PlacementMaker dress_here = [=](const Scenario& scenario) {
      PanelWrap placed;
      try {
        placed = dressing_frame_on_body(frame, scenario, settings.start_scale);
      } catch (const std::invalid_argument& error) {
        throw std::invalid_argument(std::string("Placement/Dressing: ") + error.what());
      }
      std::printf("  dressing frame: %s\n", describe_dressing_frame(frame, placed).c_str());
      std::fflush(stdout);
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
      std::vector<std::string> panel_names;
      for (const Panel& panel : panels) panel_names.push_back(panel.name);
      for (const auto& [name, degrees] : angles_deg)
        if (std::find(panel_names.begin(), panel_names.end(), name) == panel_names.end())
          throw std::invalid_argument(
              "Placement/Dressing/Panel angles: the garment has no panel '" + name + "'" +
              did_you_mean(name, panel_names));
      const std::vector<Vec3> open =
          wrap_panels_round_axis(scenario.garment, scenario.mesh, placed);
      try {
        DressingSettings writing = settings;
        writing.centre_m = placed.centre_m;
        if (scale_about_axis) writing.scale_axis = placed.axis;
        write_failed_dressing_to(scenario.parameters.output, writing);
        const DressingResult dressed = backend_registry().dressing_stage().dress(
            scenario.problem, scenario.garment, open, writing);
        print_dressing(dressed);
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
